"""Bridges that join the outside world to one end of a SerialLine.

``poll()`` moves bytes both ways: bytes from outside enter the line at the clock's current
virtual time (and are paced at the baud rate from there), bytes that have arrived at the
bridged end are written out. A client going away is reported as an event, never raised:
the device on the line keeps running and a new client may connect.

Per-connection rule (docs/reliability.md): after a client goes away the bridge *settles* —
whatever the line still delivers to its end is dropped, and a new client's bytes are held
back — until the line is idle both ways (or SETTLE_POLLS polls have passed, for a device
that never goes quiet), so one client never receives bytes that belong to another.
"""

from __future__ import annotations

import contextlib
import errno
import select
import socket
from collections import deque
from dataclasses import dataclass, field
from typing import Any

from protocols.link.line import Endpoint
from protocols.link.pty import PtyPort
from protocols.link.serial_port import open_url, read_available
from protocols.link.settings import LineSettings

MAX_EVENTS = 100  # events kept on .events; older ones are dropped
BUSY = b"camlab88: another client is connected to this line; try again later\r\n"
SETTLE_POLLS = 1000  # at most this many polls between clients spent waiting for an idle line
MAX_HELD = 1 << 20  # a new client's bytes held while settling; more and it is hung up on
WRITE_TIMEOUT = 2.0  # s a serial port may hold our bytes (handlers that support it)


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
        self._held = bytearray()  # a new client's bytes while the line settles

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
        data = self._read_outside(timeout)
        if self._settle and self._settling():
            self._held += data
            self.dropped += len(out := self.endpoint.read())
            result.dropped = len(out)
            if len(self._held) > MAX_HELD:
                self._held.clear()
                self._hang_up("sent over 1 MiB while the line settled")
            result.events, self._new_events = self._new_events, []
            return result
        if self._held:
            data, self._held = bytes(self._held) + data, bytearray()
        if data:
            self.endpoint.write(data)
            self.bytes_in += len(data)
            result.inbound = len(data)
        out = self.endpoint.read()
        if out:
            if self.connected:
                self._write_outside(out)
            if self.connected:
                self.bytes_out += len(out)
                result.outbound = len(out)
            else:
                self.dropped += len(out)
                result.dropped = len(out)
        result.events, self._new_events = self._new_events, []
        return result

    def _settling(self) -> bool:
        """Still waiting for the line to go idle after a client left (counts one poll)."""
        assert self.endpoint is not None
        line = self.endpoint.line
        self._settle -= 1
        if line.host.in_flight() == 0 and line.device.in_flight() == 0:
            self._settle = 0
        return self._settle > 0

    def _start_settling(self) -> None:
        self._settle = SETTLE_POLLS
        self._held.clear()

    def _hang_up(self, why: str) -> None:
        """Subclasses that serve clients drop the current one."""

    def close(self) -> None:
        self.closed = True

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
        return self.port.read(timeout=timeout)

    def _write_outside(self, data: bytes) -> None:
        self.port.write(data)

    def close(self) -> None:
        super().close()
        self.port.close()


class TcpBridge(Bridge):
    """A listening TCP port (127.0.0.1 by default); one client at a time, reconnects allowed.

    ``port=0`` picks a free port; read the chosen one from ``.port``.
    """

    def __init__(
        self, port: int, host: str = "127.0.0.1", *, endpoint: Endpoint | None = None
    ) -> None:
        super().__init__(endpoint)
        self._server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        try:
            self._server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            self._server.bind((host, port))
            self._server.listen(1)
            self._server.setblocking(False)
        except OSError:
            self._server.close()
            raise
        self.host, self.port = self._server.getsockname()[:2]
        self._client: socket.socket | None = None
        self._pending = bytearray()

    @property
    def connected(self) -> bool:
        return self._client is not None

    def _accept_waiting(self) -> None:
        while True:
            try:
                sock, addr = self._server.accept()
            except (BlockingIOError, InterruptedError):
                return
            if self._client is not None and self._client_gone():
                self._drop_client("closed by the client")
            if self._client is None:
                sock.setblocking(False)
                sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
                self._client = sock
                self._event("connected", f"{addr[0]}:{addr[1]}")
            else:  # one client at a time: say so, then hang up
                with contextlib.suppress(OSError):
                    sock.setblocking(False)
                    sock.send(BUSY)
                sock.close()
                self._event("refused", f"{addr[0]}:{addr[1]} (a client is already connected)")

    def disconnect(self) -> None:
        """Hang up on the current client (it may connect again)."""
        self._drop_client("hung up by the bridge")

    def _drop_client(self, why: str) -> None:
        if self._client is not None:
            with contextlib.suppress(OSError):
                self._client.close()
            self._client = None
            self._pending.clear()
            self._event("disconnected", why)
            if self.endpoint is not None:
                self._start_settling()

    def _hang_up(self, why: str) -> None:
        self._drop_client(why)

    def _read_outside(self, timeout: float) -> bytes:
        watch = [self._server] + ([self._client] if self._client else [])
        ready, _, _ = select.select(watch, [], [], max(0.0, timeout))
        data = self._read_client(ready)
        if self._server in ready:  # after the client's own news: it may just have left
            self._accept_waiting()
        return data

    def _read_client(self, ready: list) -> bytes:
        if self._client is None or (self._client not in ready and not self._client_ready()):
            return b""
        try:
            data = self._client.recv(65536)
        except (BlockingIOError, InterruptedError):
            return b""
        except OSError as exc:
            self._drop_client(f"{exc.strerror or exc}")
            return b""
        if not data:
            self._drop_client("closed by the client")
        return data

    def _client_gone(self) -> bool:
        """Whether the current client has closed or reset (looked at without reading)."""
        assert self._client is not None
        try:
            return self._client_ready() and self._client.recv(1, socket.MSG_PEEK) == b""
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
                self._drop_client(f"{exc.strerror or exc}")
                return
            del self._pending[:n]
        if len(self._pending) > 1 << 20:  # a client that never reads: bounded, then dropped
            self._drop_client("client not reading (over 1 MiB pending)")

    def close(self) -> None:
        if self.closed:
            return
        super().close()
        if self._client is not None:
            with contextlib.suppress(OSError):
                self._client.close()
            self._client = None
        self._server.close()


class SerialUrlBridge(Bridge):
    """Any pyserial URL: ``/dev/ttyUSB0`` (a real RS-232 cable), ``loop://``, ``spy://``,
    ``socket://h:p``, ``rfc2217://h:p``.

    The port is opened with the line's settings (and only options its handler supports);
    each poll takes whatever has arrived (``protocols.link.serial_port``), so any URL keeps up
    with the line.  If it cannot be opened or fails, that is reported and the bridge tries
    again on a later poll.
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
            self._event("error", f"cannot open {self.url}: {exc}")
            return
        self._event("connected", self.url)

    def _fail(self, exc: Exception) -> None:
        with contextlib.suppress(Exception):
            self._port.close()
        self._port = None
        self._retry_in = self.RETRY_POLLS
        self._event("disconnected", f"{self.url}: {exc}")

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
            return read_available(self._port, timeout)
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

    def close(self) -> None:
        if self.closed:
            return
        super().close()
        if self._port is not None:
            with contextlib.suppress(Exception):
                self._port.close()
            self._port = None
