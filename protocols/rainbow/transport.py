"""Ways a command frame reaches the device and its reply comes back.

``LoopbackTransport`` calls a handler in the same process (the default: the wiring passes
the emulator's ``Executor.handle``); ``SocketTransport`` speaks the same frames over a local
TCP socket to ``camlab88.emulator.rainbow.server``.
"""

from __future__ import annotations

import socket
from collections.abc import Callable
from typing import Protocol

from camlab88.protocols.rainbow.stream import HEADER, StreamError


class Transport(Protocol):
    def call(self, frame: bytes) -> bytes: ...
    def close(self) -> None: ...


class LoopbackTransport:
    def __init__(self, handler: Callable[[bytes], bytes]) -> None:
        self.handler = handler

    def call(self, frame: bytes) -> bytes:
        return self.handler(frame)

    def close(self) -> None:
        pass


class SocketTransport:
    def __init__(self, port: int, host: str = "127.0.0.1", timeout: float = 10.0) -> None:
        self.sock = socket.create_connection((host, port), timeout=timeout)
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)

    def _read(self, n: int) -> bytes:
        buf = bytearray()
        while len(buf) < n:
            chunk = self.sock.recv(n - len(buf))
            if not chunk:
                raise StreamError("the Rainbow closed the connection")
            buf += chunk
        return bytes(buf)

    def call(self, frame: bytes) -> bytes:
        self.sock.sendall(frame)
        head = self._read(HEADER.size)
        _, n = HEADER.unpack(head)
        return head + self._read(n)

    def close(self) -> None:
        self.sock.close()
