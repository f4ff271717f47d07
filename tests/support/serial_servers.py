"""Real far ends for pyserial URLs, on 127.0.0.1 ports the tests open themselves.

* :class:`StreamServer`: a TCP server that writes a whole stream to its first client at once
  (what ``socket://`` reads), then keeps the connection open until stopped.
* :class:`Rfc2217Server`: pyserial's own RFC 2217 server side (``serial.rfc2217.PortManager``)
  in front of a ``loop://`` "serial port": it negotiates the Telnet COM-PORT options with
  the client and then sends the stream, escaped as RFC 2217 requires.
* :func:`null_modem`: ``socat pty,raw,echo=0 pty,raw,echo=0``, two linked ptys (or None
  with the reason when socat is missing).
"""

from __future__ import annotations

import contextlib
import os
import shutil
import socket
import subprocess
import threading
import time
from collections.abc import Iterator
from pathlib import Path


class _Server:
    def __init__(self, stream: bytes) -> None:
        self.stream = stream
        self._sock = socket.create_server(("127.0.0.1", 0))
        self.port = self._sock.getsockname()[1]
        self._stop = threading.Event()
        self.received = bytearray()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self) -> None:
        self._sock.settimeout(0.1)
        while not self._stop.is_set():
            try:
                conn, _ = self._sock.accept()
            except TimeoutError:
                continue
            with conn:
                self._serve(conn)
            return

    def _serve(self, conn: socket.socket) -> None:
        raise NotImplementedError

    def stop(self) -> None:
        self._stop.set()
        self._thread.join(5)
        self._sock.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()


class StreamServer(_Server):
    """``socket://127.0.0.1:<port>``: the whole stream written at once, just after connect.

    pyserial's ``socket://`` open() ends with ``reset_input_buffer()``, which throws away
    whatever had already arrived, so the server waits SEND_AFTER s before writing."""

    SEND_AFTER = 0.2

    def _serve(self, conn: socket.socket) -> None:
        time.sleep(self.SEND_AFTER)
        conn.sendall(self.stream)
        conn.settimeout(0.1)
        while not self._stop.is_set():
            try:
                data = conn.recv(4096)
            except TimeoutError:
                continue
            except OSError:
                return
            if not data:
                return
            self.received += data


class _Connection:
    """What PortManager writes its Telnet answers to."""

    def __init__(self, conn: socket.socket) -> None:
        self.conn = conn

    def write(self, data: bytes) -> None:
        self.conn.sendall(data)


class Rfc2217Server(_Server):
    """``rfc2217://127.0.0.1:<port>``: pyserial's PortManager; the stream follows the
    option negotiation (``escape`` doubles any IAC byte, as the protocol requires).

    pyserial's client ends ``open()`` by purging its receive buffer, then the transmit
    buffer: bytes that arrive before the first purge are thrown away.  So the stream is sent
    once the client asked to purge the transmit buffer (its receive buffer is clean by then),
    not after a fixed delay, which a loaded machine outran."""

    PURGE_TRANSMIT = b"\xff\xfa\x2c\x0c\x02"  # IAC SB COM-PORT-OPTION PURGE-DATA transmit
    SEND_AFTER = 10.0  # s after the client's first bytes, if its purge was never seen

    def _serve(self, conn: socket.socket) -> None:
        import serial
        from serial import rfc2217

        port = serial.serial_for_url("loop://", timeout=0)
        manager = rfc2217.PortManager(port, _Connection(conn))
        conn.settimeout(0.05)
        first: float | None = None
        sent = False
        raw = b""
        while not self._stop.is_set():
            try:
                data = conn.recv(4096)
            except TimeoutError:
                data = None
            except OSError:
                return
            if data == b"":
                return
            if data:
                first = first or time.monotonic()
                raw = (raw + data)[-4096:]
                self.received += b"".join(manager.filter(data))
            opened = self.PURGE_TRANSMIT in raw
            if not sent and first is not None and (
                    opened or time.monotonic() - first > self.SEND_AFTER):
                conn.sendall(b"".join(manager.escape(self.stream)))
                sent = True
            port.read(4096)  # what the client wrote, echoed by loop://: not sent back


@contextlib.contextmanager
def null_modem(where: Path) -> Iterator[tuple[str, str] | str]:
    """Two ptys joined by socat: yields (end_a, end_b) paths, or a reason string."""
    socat = shutil.which("socat")
    if socat is None:
        yield "socat is not installed (apt-get install socat)"
        return
    a, b = where / "end_a", where / "end_b"
    log = where / "socat.log"
    with log.open("wb") as err:
        proc = subprocess.Popen([socat, f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"],
                                stdout=subprocess.DEVNULL, stderr=err)
    try:
        deadline = time.monotonic() + 5
        while not (a.exists() and b.exists()) and time.monotonic() < deadline:
            if proc.poll() is not None:
                break
            time.sleep(0.02)
        if not (a.exists() and b.exists()):
            yield f"socat made no ptys: {log.read_text(errors='replace')}"
            return
        yield os.fspath(a), os.fspath(b)
    finally:
        if proc.poll() is None:
            proc.terminate()
            try:
                proc.wait(5)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
