"""The optional local-socket transport, device end: serve one Rainbow on 127.0.0.1."""

from __future__ import annotations

import socket

from emulator.rainbow.executor import Executor
from protocols.rainbow.stream import REFUSED, Decoder, StreamError, encode_reply


def serve_connection(conn: socket.socket, executor: Executor) -> None:
    """Answer command frames until the client hangs up (or sends garbage)."""
    with conn:
        while True:
            data = conn.recv(1 << 16)
            if not data:
                return
            try:
                replies = executor.feed(data)
            except StreamError:
                replies = b""
            if replies:
                conn.sendall(replies)
            if executor.decoder.error is not None:
                # A broken frame cannot be resynchronised: say why, then hang up.
                conn.sendall(encode_reply(REFUSED, str(executor.decoder.error).encode()))
                executor.decoder = Decoder()
                return


def listen(port: int = 0, host: str = "127.0.0.1") -> socket.socket:
    s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    s.bind((host, port))
    s.listen(1)
    return s


def serve(executor: Executor, sock: socket.socket, connections: int | None = None) -> None:
    """Serve connections one after another (``connections`` of them, or for ever)."""
    served = 0
    while connections is None or served < connections:
        conn, _ = sock.accept()
        serve_connection(conn, executor)
        served += 1
