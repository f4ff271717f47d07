"""A serial tablet on a real port, a pty, or any pyserial URL."""

from __future__ import annotations

import select
import time
from collections.abc import Callable
from dataclasses import replace

import serial

from protocols.tablets import wacom4
from protocols.tablets.base import TabletParser
from protocols.tablets.events import DeviceReply, TabletEvent
from protocols.tablets.line_setup import LineSetup
from protocols.tablets.registry import make_parser, resolve
from protocols.tablets.sources import SourceLost, SourceSpec, TabletSource

REPLY_TIMEOUT = 1.0  # the kernel waits HZ for a Wacom reply (a PenPartner sends no CR)
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


class SerialSource(TabletSource):
    def __init__(self, spec: SourceSpec, on_raw: Callable[[bytes], None] | None = None,
                 sleep: Callable[[float], None] = time.sleep) -> None:
        protocol_spec, _ = resolve(spec.protocol or "")
        self.spec = spec
        self.line: LineSetup = protocol_spec.line
        self.name = spec.text or spec.target
        self.on_raw = on_raw
        self._sleep = sleep
        bytesize, parity, stopbits = self.line.wire
        baud = spec.baud or self.line.baud
        try:
            self.port = serial.serial_for_url(
                spec.target, baudrate=baud, bytesize=bytesize, parity=_PARITY[parity],
                stopbits=stopbits, xonxoff=self.line.xonxoff, rtscts=self.line.rtscts,
                timeout=0, do_not_open=False,
            )
        except (serial.SerialException, OSError, ValueError) as exc:
            raise SourceLost(f"{spec.text}: cannot open {spec.target}: {exc}") from exc
        parmrk = spec.kind == "serial" and parity != "N" and _enable_parmrk(self.port)
        self.parser: TabletParser = make_parser(spec.protocol or "", spec.options, parmrk=parmrk)
        self.model = self.parser.model
        self.replies: list[DeviceReply] = []
        self._t0 = self._last_byte = time.monotonic()  # event times count from opening
        if spec.init and self.line.init:
            try:
                self.initialise()
            except BaseException:
                self.close()
                raise

    # -- start-up -----------------------------------------------------------------------
    def initialise(self) -> None:
        """Send the protocol's reset/identify sequence and adopt what the tablet says."""
        for step in self.line.init:
            if step.baud and step.baud != self.port.baudrate:
                try:
                    self.port.baudrate = step.baud
                except (serial.SerialException, OSError, ValueError):
                    pass  # sockets and loopbacks have no baud rate to set
            self._write(step.data)
            if step.expect_reply:
                self._await_reply(step.wait, step.data)
            elif step.wait:
                self._sleep(step.wait)
        if isinstance(self.parser, wacom4.Wacom4Parser):
            self._configure_wacom()
        self.model = self.parser.model

    def _await_reply(self, limit: float, command: bytes) -> None:
        """Wait for the answer to a query.  Wacom answers in ASCII (a ``~`` reply); the
        Summagraphics ``a`` answer is a report whose X/Y are the maximum coordinates."""
        deadline = time.monotonic() + limit
        before = len(self.replies)
        while time.monotonic() < deadline:
            events = self.read(timeout=0.05)
            if len(self.replies) > before:
                return
            if events and command == b"a":
                self.model = self.parser.model = replace(
                    self.parser.model, max_x=events[0].x, max_y=events[0].y)
                return
        self.parser.flush()
        self.replies.extend(self.parser.take_replies())

    def _configure_wacom(self) -> None:
        parser = self.parser
        assert isinstance(parser, wacom4.Wacom4Parser)
        identity = None
        for reply in self.replies:
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
        setup = identity.setup_string if identity else wacom4.WacomIdentity("UD", (1, 4),
                                                                          "").setup_string
        self._write(setup)

    # -- I/O -------------------------------------------------------------------------------
    def _write(self, data: bytes) -> None:
        try:
            self.port.write(data)
        except (serial.SerialException, OSError) as exc:
            raise SourceLost(f"{self.name}: write failed: {exc}") from exc

    def write(self, data: bytes) -> None:
        self._write(data)

    def _wait_readable(self, timeout: float) -> None:
        try:
            fd = self.port.fileno()
        except (AttributeError, OSError, ValueError, serial.SerialException):
            fd = None
        if fd is not None:
            select.select([fd], [], [], timeout)
            return
        deadline = time.monotonic() + timeout  # URL handlers without a file descriptor
        while time.monotonic() < deadline and not self.port.in_waiting:
            self._sleep(0.002)

    def read(self, timeout: float = 0.0) -> list[TabletEvent]:
        """Events decoded from whatever arrived, waiting up to ``timeout`` s for the first byte.

        The port stays non-blocking (changing pyserial's timeout reconfigures the tty)."""
        try:
            data = self.port.read(self.port.in_waiting or 1)
            if not data and timeout > 0:
                self._wait_readable(timeout)
                data = self.port.read(self.port.in_waiting or 1)
        except (serial.SerialException, OSError, TypeError) as exc:
            raise SourceLost(f"{self.name}: {exc}") from exc
        now = time.monotonic()
        events: list[TabletEvent] = []
        if data:
            self._last_byte = now
            if self.on_raw is not None:
                self.on_raw(data)
            events = self.parser.feed(data, now - self._t0)
        elif now - self._last_byte > REPLY_TIMEOUT:
            events = self.parser.flush(now - self._t0)
        self.replies.extend(self.parser.take_replies())
        return events

    def close(self) -> None:
        try:
            self.port.close()
        except (serial.SerialException, OSError):
            pass
