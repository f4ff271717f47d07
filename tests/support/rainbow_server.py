"""A Rainbow server on a 127.0.0.1 port the test opens, served in a thread."""

from __future__ import annotations

import threading

from camlab88.emulator.rainbow import Rainbow
from camlab88.emulator.rainbow.executor import Executor
from camlab88.emulator.rainbow.server import ServerStats, listen, serve


def serving(connections: int, device: Rainbow | None = None,
            **kw: float) -> tuple[int, threading.Thread, list[ServerStats]]:
    """``serve`` (``kw``: its timeouts and poll) for ``connections`` connections on a fresh
    port, in a daemon thread that closes the socket when it returns: the port, the thread, and
    a list that receives the server's statistics as it returns."""
    sock = listen(0)
    out: list[ServerStats] = []

    def run() -> None:
        try:
            out.append(serve(Executor(device or Rainbow()), sock, connections, **kw))
        finally:
            sock.close()

    t = threading.Thread(target=run, daemon=True)
    t.start()
    return sock.getsockname()[1], t, out
