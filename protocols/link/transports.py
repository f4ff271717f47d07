"""Bridges that join the outside world to one end of a SerialLine.

``poll()`` moves bytes both ways: bytes from outside enter the line at the clock's current
virtual time (and are paced at the baud rate from there), bytes that have arrived at the
bridged end are written out. A client going away is reported as an event, never raised:
the device on the line keeps running and a new client may connect.

Per-connection rules (docs/reliability.md, "Listeners"):

* Bounded: a bridge takes bytes from outside only while fewer than MAX_QUEUED are waiting to
  go down the line; the rest wait outside (TCP flow control, the pty's kernel buffer blocks
  the writer), as a real 9600-baud port makes a fast writer wait. Memory does not grow with
  what a client sends.
* Isolated: when the line changes hands (a new client connects after one left, or the bridge
  hangs up on one) the line hangs up (``Endpoint.hang_up``): what the old client queued and
  what was queued for it are dropped. Then the bridge *settles*: what the line still delivers
  to its end (the device's answers to bytes that had already reached it) is dropped, and the
  new client is not read, until the line is idle both ways (or SETTLE_POLLS polls have
  passed, for a device that never goes quiet). One client never receives bytes that belong
  to another, and a new client starts on an empty line. A client that closes while nobody is
  waiting still has the bytes it sent go down the line.
"""

from __future__ import annotations

import contextlib
import errno
import os
import select
import socket
import time
from collections import deque
from dataclasses import dataclass, field
from typing import Any

from camlab88.protocols.link.line import Endpoint
from camlab88.protocols.link.pty import PtyPort
from camlab88.protocols.link.serial_port import CHUNK, open_url, read_available
from camlab88.protocols.link.settings import LineSettings

MAX_EVENTS = 100  # events kept on .events; older ones are dropped
BUSY = b"camlab88: another client is connected to this line; try again later\r\n"
SETTLE_POLLS = 1000  # at most this many polls between clients spent waiting for an idle line
MAX_QUEUED = 4096  # bytes from outside waiting to go down the line (a tty driver's buffer)
# taken again once no more than this many wait: a writer flat out is read in big gulps, not
# a few bytes every poll (the line never runs dry: 2048 bytes are 2 s at 9600 baud)
REFILL_AT = MAX_QUEUED // 2
_RDHUP = getattr(select, "POLLRDHUP", 0)  # Linux: the peer shut its sending side
IDLE_TIMEOUT = 60.0  # s of line time a silent client keeps the line from a newcomer (commands)
# s of line time a client may hold the line while others try to connect, however steadily it
# sends (a byte a second kept it for ever): then the next newcomer takes the line
SESSION_TIME = 180.0
PROBE_MS = 50  # how long a newcomer's arrival waits for a probed client's reset
PROBE_EVERY = 1.0  # s between two probes of one client (a late reset is seen at the next poll)
RCVBUF = 16384  # bytes of kernel receive buffer per client (Linux doubles it)
BACKLOG = 128  # connections the kernel queues between two polls (a burst is not dropped)
WRITE_TIMEOUT = 2.0  # s a serial port may hold our bytes (handlers that support it)


def _close_quietly(handle: Any) -> None:
    """Close a socket or serial port that may already be broken: the bridge is letting go
    of it, so an error closing it changes nothing."""
    with contextlib.suppress(Exception):
        handle.close()


def _reason(exc: BaseException) -> str:
    """The OS's reason once (pyserial's message repeats the port and nests the OS error)."""
    code = getattr(exc, "errno", None)
    return os.strerror(code) if isinstance(code, int) and code > 0 else str(exc)


@dataclass(frozen=True)
class BridgeEvent:
    kind: str  # "connected", "disconnected", "refused", "error"
    detail: str = ""


@dataclass
class PollResult:
    inbound: int = 0  # bytes from outside put on the line
    outbound: int = 0  # bytes from the line written outside
    dropped: int = 0  # bytes from the line with nobody outside to take them
    events: list[BridgeEvent] = field(default_factory=list)


class Bridge:
    """Common part: attach to an endpoint, poll, report events, count bytes."""

    def __init__(self, endpoint: Endpoint | None = None) -> None:
        self.endpoint = endpoint
        self.events: deque[BridgeEvent] = deque(maxlen=MAX_EVENTS)
        self.bytes_in = 0
        self.bytes_out = 0
        self.dropped = 0
        self.closed = False
        self._new_events: list[BridgeEvent] = []
        self._settle = 0  # polls left to wait for the line to go idle between clients

    def attach(self, endpoint: Endpoint) -> None:
        self.endpoint = endpoint

    def _event(self, kind: str, detail: str = "") -> None:
        event = BridgeEvent(kind, detail)
        self.events.append(event)
        self._new_events.append(event)

    # Subclasses implement these three.
    @property
    def connected(self) -> bool:
        raise NotImplementedError

    def _read_outside(self, timeout: float) -> bytes:
        raise NotImplementedError

    def _write_outside(self, data: bytes) -> None:
        raise NotImplementedError

    def poll(self, timeout: float = 0.0) -> PollResult:
        """Move bytes both ways, waiting up to ``timeout`` wall seconds for outside input."""
        if self.endpoint is None:
            raise RuntimeError(f"{type(self).__name__} is not attached to a line endpoint")
        if self.closed:
            raise ValueError(f"{type(self).__name__} is closed")
        result = PollResult()
        settling = bool(self._settle) and self._settling()
        data = self._read_outside(timeout)  # at most self._room() bytes
        if data:
            self.endpoint.write(data)
            self.bytes_in += len(data)
            result.inbound = len(data)
        out = self.endpoint.read()
        if out and self.connected and not settling:
            self._write_outside(out)
        if out and self.connected and not settling:
            self.bytes_out += len(out)
            result.outbound = len(out)
        elif out:
            self.dropped += len(out)
            result.dropped = len(out)
        result.events, self._new_events = self._new_events, []
        return result

    def _room(self) -> int:
        """How many bytes the bridge may take from outside now (none while settling)."""
        assert self.endpoint is not None
        if self._settle:
            return 0
        queued = self.endpoint.queued()
        if queued > REFILL_AT:  # seconds of line time still waiting: no read (a syscall)
            return 0
        return max(0, MAX_QUEUED - queued)

    def _settling(self) -> bool:
        """Still waiting for the line to go idle after a client left (counts one poll)."""
        assert self.endpoint is not None
        line = self.endpoint.line
        self._settle -= 1
        if line.host.in_flight() == 0 and line.device.in_flight() == 0:
            self._settle = 0
        return self._settle > 0

    def _start_settling(self) -> None:
        """A client left: the line hangs up (its bytes and the bytes for it are dropped)."""
        assert self.endpoint is not None
        self.dropped += self.endpoint.hang_up()
        self._settle = SETTLE_POLLS

    def close(self) -> None:
        """Release the bridge's ports (once: closing again does nothing)."""
        if self.closed:
            return
        self.closed = True
        self._release()

    def _release(self) -> None:
        """Close what the bridge opened to the outside (subclasses)."""

    def __enter__(self) -> Any:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class PtyBridge(Bridge):
    """A pseudo-terminal: any program opens ``slave_path`` as its serial port."""

    def __init__(self, endpoint: Endpoint | None = None, port: PtyPort | None = None) -> None:
        super().__init__(endpoint)
        self.port = port or PtyPort()

    @property
    def slave_path(self) -> str:
        return self.port.slave_path

    @property
    def connected(self) -> bool:
        return not self.port.closed  # the pty exists whether or not a program has it open

    def _read_outside(self, timeout: float) -> bytes:
        room = self._room()
        if room == 0:  # the writer waits in the kernel's pty buffer (its write blocks)
            self.port.flush()
            return b""
        return self.port.read(min(room, 4096), timeout=timeout)

    def _write_outside(self, data: bytes) -> None:
        self.port.write(data)

    def _release(self) -> None:
        self.port.close()


class TcpBridge(Bridge):
    """A listening TCP port (127.0.0.1 by default); one client at a time, reconnects allowed.

    ``port=0`` picks a free port; read the chosen one from ``.port``. With ``idle_timeout``
    (seconds of line time), a client that has sent nothing for that long gives way to a
    newcomer instead of the newcomer being refused; with ``session_time``, a client that has
    held the line that long gives way to the next newcomer whatever it sends (a refused
    newcomer is told how long at most it has to wait).
    """

    def __init__(
        self, port: int, host: str = "127.0.0.1", *, endpoint: Endpoint | None = None,
        idle_timeout: float | None = None, session_time: float | None = None,
    ) -> None:
        super().__init__(endpoint)
        self.idle_timeout = idle_timeout
        self.session_time = session_time
        self._heard_at = 0.0  # line time the client last sent something
        self._since = 0.0  # line time the client connected
        self._server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        try:
            self._server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            # a small receive window (clients inherit it): what a client has sent and the line
            # has not taken waits in the client's own buffers, not in ours
            self._server.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, RCVBUF)
            self._server.bind((host, port))
            self._server.listen(BACKLOG)
            self._server.setblocking(False)
        except OSError:
            self._server.close()
            raise
        self.host, self.port = self._server.getsockname()[:2]
        self._client: socket.socket | None = None
        self._pending = bytearray()
        self._left = False  # a client left bytes on the line; hang it up for the next one
        self._probed_at = -PROBE_EVERY

    @property
    def connected(self) -> bool:
        return self._client is not None

    def _accept_waiting(self) -> None:
        while True:
            try:
                sock, addr = self._server.accept()
            except (BlockingIOError, InterruptedError):
                return
            if self._client is not None and (self._client_gone() or self._client_orphaned()):
                self._drop_client("closed by the client", hang_up=True)
            elif self._client is not None and self._client_idle():
                self._drop_client(f"silent for {self.idle_timeout:g} s of line time while "
                                  "another client waited", hang_up=True)
            elif self._client is not None and self._client_overstayed():
                self._drop_client(f"held the line for {self.session_time:g} s of line time "
                                  "while another client waited", hang_up=True)
            if self._client is None:
                if self._left:  # what the last client left on the line is not for this one
                    self._left = False
                    self._start_settling()
                sock.setblocking(False)
                sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
                self._client, self._probed_at = sock, -PROBE_EVERY
                self._heard_at = self._since = self._line_time()
                self._event("connected", f"{addr[0]}:{addr[1]}")
            else:  # one client at a time: say so (and for how long at most), then hang up
                with contextlib.suppress(OSError):
                    sock.setblocking(False)
                    sock.send(self._busy())
                sock.close()
                self._event("refused", f"{addr[0]}:{addr[1]} (a client is already connected)")

    def disconnect(self, why: str = "hung up by the bridge") -> None:
        """Hang up on the current client (it may connect again): the line hangs up too."""
        self._drop_client(why, hang_up=True)

    def _drop_client(self, why: str, hang_up: bool) -> None:
        """Close the client's connection. ``hang_up``: the line hangs up now (the bridge
        ended it, or a newcomer is waiting); otherwise bytes it sent that are already on the
        line still go down it (``nc host port < plot`` draws the whole plot), and the line
        hangs up when the next client connects."""
        if self._client is not None:
            _close_quietly(self._client)
            self._client = None
            self._pending.clear()
            self._event("disconnected", why)
            self._left = self.endpoint is not None
            if hang_up and self._left:
                self._left = False
                self._start_settling()

    def _read_outside(self, timeout: float) -> bytes:
        client, room = self._client, self._room()
        watch = [self._server] + ([client] if client is not None and room else [])
        ready, _, _ = select.select(watch, [], [], max(0.0, timeout))
        data = self._read_client(ready, room) if client is not None and room else b""
        if self._server in ready:  # after the client's own news: it may just have left
            self._accept_waiting()
        return data if self._client is client else b""  # a client gone: its bytes too

    def _read_client(self, ready: list, room: int) -> bytes:
        assert self._client is not None
        if self._client not in ready and not self._client_ready():
            return b""
        try:
            data = self._client.recv(min(65536, room))
        except (BlockingIOError, InterruptedError):
            return b""
        except OSError as exc:
            self._drop_client(f"{exc.strerror or exc}", hang_up=False)
            return b""
        if not data:
            self._drop_client("closed by the client", hang_up=False)
        self._heard_at = self._line_time()
        return data

    def _line_time(self) -> float:
        return self.endpoint.line.clock.now if self.endpoint is not None else 0.0

    def _client_idle(self) -> bool:
        """Whether the client has been silent for ``idle_timeout`` (while a newcomer waits;
        a client whose bytes wait for the line is not silent)."""
        return (self.idle_timeout is not None and not self._client_ready()
                and self._line_time() - self._heard_at >= self.idle_timeout)

    def _client_overstayed(self) -> bool:
        """Whether the client has held the line for ``session_time`` of line time (judged
        when a newcomer connects: a client alone keeps the line as long as it likes)."""
        return (self.session_time is not None
                and self._line_time() - self._since >= self.session_time)

    def _busy(self) -> bytes:
        """The refusal a newcomer reads: with a session time, when the line is free at the
        latest (in line time, which is wall time while serving)."""
        if self.session_time is None:
            return BUSY
        left = max(0.0, self.session_time - (self._line_time() - self._since))
        return (f"camlab88: another client is connected to this line; it gives way to the "
                f"next client in at most {left:.0f} s\r\n").encode()

    def _client_orphaned(self) -> bool:
        """Whether a client whose bytes wait for the line has in fact closed: its close sits
        behind bytes its kernel has not yet sent us, so only a probe tells. One urgent
        (out-of-band) byte: a closed socket answers any data with a reset; a live client
        never sees it in its data (only a program that asked for out-of-band data inline
        would). Asked only when a newcomer is waiting and the client's bytes are waiting."""
        assert self._client is not None
        now = time.monotonic()
        if not self._client_ready() or now - self._probed_at < PROBE_EVERY:
            return False  # nothing of its waits (a close would have shown), or probed lately
        self._probed_at = now  # a flood of newcomers cannot stall the line with probes
        try:
            self._client.send(b"\0", socket.MSG_OOB)
        except (BlockingIOError, InterruptedError):
            return False
        except OSError:
            return True
        return self._client_gone(wait_ms=PROBE_MS)

    def _client_gone(self, wait_ms: int = 0) -> bool:
        """Whether the current client has shut its sending side, closed or reset, looked
        at without reading (POLLRDHUP sees it even with bytes of its still unread)."""
        assert self._client is not None
        watch = select.poll()
        watch.register(self._client, _RDHUP | (0 if wait_ms else select.POLLIN))
        events = watch.poll(wait_ms)
        if not events:
            return False
        if events[0][1] & (select.POLLHUP | select.POLLERR | _RDHUP):
            return True
        try:
            return self._client.recv(1, socket.MSG_PEEK) == b""
        except (BlockingIOError, InterruptedError):
            return False
        except OSError:
            return True

    def _client_ready(self) -> bool:
        assert self._client is not None
        ready, _, _ = select.select([self._client], [], [], 0)
        return bool(ready)

    def _write_outside(self, data: bytes) -> None:
        assert self._client is not None
        self._pending += data
        while self._pending:
            try:
                n = self._client.send(self._pending)
            except (BlockingIOError, InterruptedError):
                break
            except OSError as exc:
                self._drop_client(f"{exc.strerror or exc}", hang_up=False)
                return
            del self._pending[:n]
        if len(self._pending) > 1 << 20:  # a client that never reads: bounded, then dropped
            self._drop_client("client not reading (over 1 MiB pending)", hang_up=True)

    def _release(self) -> None:
        if self._client is not None:
            _close_quietly(self._client)
            self._client = None
        self._server.close()


class SerialUrlBridge(Bridge):
    """Any pyserial URL: ``/dev/ttyUSB0`` (a real RS-232 cable), ``loop://``, ``spy://``,
    ``socket://h:p``, ``rfc2217://h:p``.

    The port is opened with the line's settings (and only options its handler supports);
    each poll takes whatever has arrived (``camlab88.protocols.link.serial_port``), so any URL
    keeps up with the line.  If it cannot be opened or fails, that is reported and the bridge tries
    again on a later poll; a retry that fails the same way again is not reported again, and
    the port coming back is (``connected``, "... is back").
    """

    RETRY_POLLS = 25  # polls between reopen attempts after a failure

    def __init__(
        self,
        url: str,
        settings: LineSettings | None = None,
        *,
        endpoint: Endpoint | None = None,
        xonxoff: bool = False,
    ) -> None:
        super().__init__(endpoint)
        self.url = url
        self.settings = settings or LineSettings()
        self.xonxoff = xonxoff  # host-OS flow control on the real port (off: the line does it)
        self._port: Any = None
        self._retry_in = 0
        self._trouble: str | None = None  # the failure last reported, until the port is back
        self._open()

    @property
    def connected(self) -> bool:
        return self._port is not None

    def _open(self) -> None:
        import serial

        try:
            self._port = open_url(self.url, write_timeout=WRITE_TIMEOUT, xonxoff=self.xonxoff,
                                  **self.settings.pyserial_kwargs())
        except (serial.SerialException, OSError, ValueError) as exc:
            self._port = None
            self._retry_in = self.RETRY_POLLS
            why = f"cannot open {self.url}: {_reason(exc)}"
            if why != self._trouble:  # the same failure again is not news
                self._trouble = why
                self._event("error", why + " (retrying)" if self.events else why)
            return
        back, self._trouble = self._trouble is not None, None
        self._event("connected", f"{self.url} is back" if back else self.url)

    def _fail(self, exc: Exception) -> None:
        _close_quietly(self._port)
        self._port = None
        self._retry_in = self.RETRY_POLLS
        self._trouble = f"{self.url}: {exc}"
        self._event("disconnected", f"{self.url}: {exc} (retrying)")

    def _read_outside(self, timeout: float) -> bytes:
        import serial

        if self._port is None:
            self._retry_in -= 1
            if self._retry_in > 0:
                return b""
            self._open()
            if self._port is None:
                return b""
        try:
            # at most self._room() bytes: the rest waits in the port, as with the pty
            return read_available(self._port, timeout, limit=min(CHUNK, self._room()))
        except (serial.SerialException, OSError) as exc:
            if isinstance(exc, OSError) and exc.errno == errno.EINTR:
                return b""
            self._fail(exc)
            return b""

    def _write_outside(self, data: bytes) -> None:
        import serial

        try:
            self._port.write(data)
        except (serial.SerialException, OSError) as exc:
            self._fail(exc)

    def _release(self) -> None:
        if self._port is not None:
            _close_quietly(self._port)
            self._port = None
