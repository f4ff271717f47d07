"""A serial tablet on a real port, a pty, or any pyserial URL."""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import replace

import serial

from camlab88.protocols.link.serial_port import descriptor, open_url, read_available
from camlab88.protocols.tablets import wacom4
from camlab88.protocols.tablets.base import TabletParser
from camlab88.protocols.tablets.events import DeviceReply, TabletEvent
from camlab88.protocols.tablets.line_setup import LineSetup
from camlab88.protocols.tablets.registry import make_parser, resolve
from camlab88.protocols.tablets.sources import SourceLost, SourceSpec, TabletSource

REPLY_TIMEOUT = 1.0  # the kernel waits HZ for a Wacom reply (a PenPartner sends no CR)
FLUSH_QUIET = 0.05  # s of silence that ends a flush
FLUSH_LIMIT = 1.0  # a flush never waits longer than this
WRITE_TIMEOUT = 2.0  # a port that will not take a few command bytes in this long is dead
SIZE_SETTLE = 0.1  # after a size reply, s to watch for more reports (a streaming tablet)
MIN_SIZE = 100  # a "maximum coordinate" below this is not a tablet's size
# A tablet streaming in proximity sends a report at least every few tens of ms; this long a
# silence with the tip down means the stream broke (the input layer acts on it).
STALL_RELEASE = 0.5
STALL_FALLBACK = 2.0
_PARITY = {"N": serial.PARITY_NONE, "E": serial.PARITY_EVEN, "O": serial.PARITY_ODD}


def _enable_parmrk(port: serial.Serial) -> bool:
    """Ask the OS to mark parity errors (FF 00 x) instead of passing bad bytes silently."""
    try:
        import termios
    except ImportError:  # Windows: the driver drops bad bytes; nothing to mark
        return False
    try:
        fd = port.fileno()
        attrs = termios.tcgetattr(fd)
        attrs[0] |= termios.INPCK | termios.PARMRK
        attrs[0] &= ~(termios.IGNPAR | termios.ISTRIP)
        termios.tcsetattr(fd, termios.TCSANOW, attrs)
        return True
    except (OSError, AttributeError, ValueError, termios.error):
        return False


def _set_software_flow(port: serial.Serial, xoff_to_tablet: bool) -> None:
    """IXON off (0x11/0x13 from the tablet are data), IXOFF as the protocol says.

    pyserial's ``xonxoff`` sets both directions at once, so the port is opened without it
    and IXOFF is set here on a POSIX tty; a socket or loopback URL has no tty to set."""
    try:
        import termios
    except ImportError:  # Windows: pyserial's xonxoff=False already leaves both off
        return
    fd = descriptor(port)
    if fd is None:
        return  # not a file descriptor (rfc2217://, loop://)
    try:
        attrs = termios.tcgetattr(fd)
    except termios.error:
        return  # not a tty (socket://)
    attrs[0] &= ~(termios.IXON | termios.IXANY)
    attrs[0] = attrs[0] | termios.IXOFF if xoff_to_tablet else attrs[0] & ~termios.IXOFF
    termios.tcsetattr(fd, termios.TCSANOW, attrs)


def _why(exc: BaseException) -> str:
    """The reason a port did not open, once: pyserial's message repeats the port name and
    nests the OS error ('could not open port X: [Errno 2] No such file ...: 'X'')."""
    errno = getattr(exc, "errno", None)
    if isinstance(errno, int) and errno > 0:
        import os

        return os.strerror(errno)
    return str(exc)


def configure_wacom(parser: TabletParser, replies: list[DeviceReply]) -> bytes:
    """Adopt a Wacom IV's ``~#``/``~R``/``~C`` answers (model, tilt, size); returns the
    model's setup string to send.  Also what a replay applies to the recorded replies."""
    assert isinstance(parser, wacom4.Wacom4Parser)
    identity = None
    for reply in replies:
        try:
            if reply.text.startswith("~#"):
                identity = wacom4.parse_model_reply(reply.text)
                parser.identify(identity)
            elif reply.text.startswith("~R"):
                settings = wacom4.parse_settings_reply(reply.text)
                parser.set_tilt(settings.packet_length == 9)
                if identity is None or identity.lines_per_inch is None:
                    parser.model = replace(parser.model, lines_per_inch=settings.res_x)
            elif reply.text.startswith("~C"):
                mx, my = wacom4.parse_coords_reply(reply.text)
                parser.model = replace(parser.model, max_x=mx, max_y=my)
        except ValueError:
            continue  # a garbled reply: keep the defaults
    fallback = wacom4.WacomIdentity("UD", (1, 4), "")
    return (identity or fallback).setup_string


class SerialSource(TabletSource):
    def __init__(self, spec: SourceSpec, on_raw: Callable[[bytes], None] | None = None,
                 sleep: Callable[[float], None] = time.sleep,
                 clock: Callable[[], float] = time.monotonic) -> None:
        protocol_spec, _ = resolve(spec.protocol or "")
        self.spec = spec
        self.line: LineSetup = protocol_spec.line
        self.name = spec.text or spec.target
        self.on_raw = on_raw
        self.on_flush: Callable[[], None] | None = None  # a silence ended a partial reply
        self._sleep = sleep
        self.clock = clock  # times events and silences (injectable: tests stay deterministic)
        self.stall_release, self.stall_fallback = STALL_RELEASE, STALL_FALLBACK
        self.size_notes: list[str] = []
        bytesize, parity, stopbits = self.line.wire
        baud = spec.baud or self.line.baud
        try:
            self.port = open_url(
                spec.target, baudrate=baud, bytesize=bytesize, parity=_PARITY[parity],
                stopbits=stopbits, xonxoff=False, rtscts=self.line.rtscts,
                write_timeout=WRITE_TIMEOUT,
            )
            _set_software_flow(self.port, self.line.xoff_to_tablet)
        except (serial.SerialException, OSError, ValueError) as exc:
            raise SourceLost(f"{spec.text}: cannot open {spec.target}: {_why(exc)}") from exc
        parmrk = spec.kind == "serial" and parity != "N" and _enable_parmrk(self.port)
        self.parser: TabletParser = make_parser(spec.protocol or "", spec.options, parmrk=parmrk)
        self.model = self.parser.model
        self.replies: list[DeviceReply] = []
        self._t0 = self.last_data = clock()  # event times count from opening
        self.heard = 0  # bytes received since opening (start-up replies and reports)
        if spec.init and self.line.init:
            try:
                self.initialise()
            except BaseException:
                self.close()
                raise

    # -- start-up -----------------------------------------------------------------------
    def initialise(self) -> None:
        """Send the protocol's reset/identify sequence and adopt what the tablet says.

        Raises SourceLost, naming what to check, if the protocol has queries and not one
        byte came back: nothing is printed as found when nothing answered."""
        started = time.monotonic()
        for step in self.line.init:
            if step.baud and step.baud != self.port.baudrate:
                try:
                    self.port.baudrate = step.baud
                except (serial.SerialException, OSError, ValueError):
                    pass  # sockets and loopbacks have no baud rate to set
                # pyserial rewrites the whole termios on a speed change
                _set_software_flow(self.port, self.line.xoff_to_tablet)
            self._write(step.data)
            if step.size_reply:
                self._await_size(step.wait, step.data)
            elif step.expect_reply:
                self._await_reply(step.wait, step.data)
            elif step.wait:
                self._sleep(step.wait)
            if step.flush:
                self._flush_input()
        queries = [s.data for s in self.line.init if s.expect_reply]
        if queries and not self.heard:
            raise SourceLost(self._no_answer(queries, time.monotonic() - started))
        if isinstance(self.parser, wacom4.Wacom4Parser):
            self._configure_wacom()
        self.model = self.parser.model

    def _no_answer(self, queries: list[bytes], waited: float) -> str:
        asked = ", ".join(repr(q.strip(b"\r").decode("ascii", "replace")) for q in queries)
        baud = self.spec.baud or self.line.baud
        return (f"{self.name}: no answer from a tablet in {waited:.1f} s to the "
                f"{self.spec.protocol} start-up queries ({asked}); check the cable (plugged "
                "in, the tablet switched on; a USB-serial adapter's port is /dev/ttyUSB0), "
                f"the protocol (?protocol={self.spec.protocol}: is it that kind of tablet?) "
                f"and the line speed ({baud} baud, {self.line.describe()}; ?baud=N)")

    def _flush_input(self) -> None:
        """Drop the reports already on their way (sent before prompt/stop mode took hold):
        read and discard until the line has been quiet for ``FLUSH_QUIET`` s (bounded, in
        case the tablet ignored the command and keeps streaming)."""
        try:
            self.port.reset_input_buffer()
        except (serial.SerialException, OSError, AttributeError):
            pass
        deadline = time.monotonic() + FLUSH_LIMIT
        try:
            while time.monotonic() < deadline:
                dropped = read_available(self.port, FLUSH_QUIET, self._sleep)
                if not dropped:
                    break
                self.heard += len(dropped)
        except (serial.SerialException, OSError, TypeError) as exc:
            raise SourceLost(f"{self.name}: {exc}") from exc
        self.parser = make_parser(self.spec.protocol or "", self.spec.options,
                                  parmrk=self.parser._parmrk is not None)

    def _await_reply(self, limit: float, command: bytes) -> None:
        """Wait for an ASCII answer to a query (a Wacom ``~`` reply)."""
        deadline = time.monotonic() + limit
        before = len(self.replies)
        while time.monotonic() < deadline:
            self.read(timeout=0.05)
            if len(self.replies) > before:
                return
        self.parser.flush()
        self.replies.extend(self.parser.take_replies())

    def _await_size(self, limit: float, command: bytes) -> None:
        """Summagraphics ``a`` / CalComp ``ESC%VS``: the answer is one report whose X/Y are
        the maximum coordinates.  Adopt it only if it is plausible: exactly one report (a
        tablet still streaming sends more) with a size no tablet would be below."""
        self.parser.range_check = False  # the real tablet may be larger than the default
        events: list[TabletEvent] = []
        deadline = time.monotonic() + limit
        try:
            while time.monotonic() < deadline and not events:
                events += self.read(timeout=0.05)
            settle = min(deadline, time.monotonic() + SIZE_SETTLE)
            while events and time.monotonic() < settle:
                events += self.read(timeout=0.02)
        finally:
            self.parser.range_check = self.parser.checks_range
        what = command.strip(b"\x1b%\r").decode("ascii", "replace")
        if len(events) == 1 and events[0].x >= MIN_SIZE and events[0].y >= MIN_SIZE:
            self.model = self.parser.model = replace(
                self.parser.model, max_x=events[0].x, max_y=events[0].y)
            return
        if not events:
            note = f"no answer to {what!r}"
        elif len(events) > 1:
            note = f"{len(events)} reports after {what!r} (still streaming?)"
        else:
            note = f"implausible size {events[0].x} x {events[0].y} after {what!r}"
        m = self.parser.model
        self.size_notes.append(f"{self.name}: {note}; keeping 0..{m.max_x} x 0..{m.max_y}")

    def _configure_wacom(self) -> None:
        self._write(configure_wacom(self.parser, self.replies))

    # -- I/O -------------------------------------------------------------------------------
    def _write(self, data: bytes) -> None:
        try:
            self.port.write(data)
        except serial.SerialTimeoutException:
            # held by CTS or XOFF that never comes back: no tablet is listening
            raise SourceLost(f"{self.name}: the port took no bytes for {WRITE_TIMEOUT:g} s "
                             "(is a tablet connected and switched on?)") from None
        except (serial.SerialException, OSError) as exc:
            raise SourceLost(f"{self.name}: write failed: {exc}") from exc

    def write(self, data: bytes) -> None:
        self._write(data)

    def read(self, timeout: float = 0.0) -> list[TabletEvent]:
        """Events decoded from whatever arrived, waiting up to ``timeout`` s for the first byte.

        The port stays non-blocking (changing pyserial's timeout reconfigures the tty)."""
        try:
            data = read_available(self.port, timeout, self._sleep)
        except (serial.SerialException, OSError, TypeError) as exc:
            raise SourceLost(f"{self.name}: {exc}") from exc
        now = self.clock()
        events: list[TabletEvent] = []
        if data:
            self.heard += len(data)
            self.last_data = now
            if self.on_raw is not None:
                self.on_raw(data)
            events = self.parser.feed(data, now - self._t0)
        elif now - self.last_data > REPLY_TIMEOUT:
            events = self.parser.flush(now - self._t0)
        replies = self.parser.take_replies()
        if not data and (events or replies) and self.on_flush is not None:
            self.on_flush()  # the silence decided something: a replay must flush here too
        self.replies.extend(replies)
        return events

    def close(self) -> None:
        try:
            self.port.close()
        except (serial.SerialException, OSError):
            pass
