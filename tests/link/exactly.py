"""Reading an exact number of bytes from a real port or socket in the link tests: every read
is bounded by the port's or socket's own timeout, and a short read fails naming what came."""

from __future__ import annotations

from collections.abc import Callable


def read_exactly(read: Callable[[int], bytes], n: int) -> bytes:
    """``n`` bytes from ``read`` (``port.read``, ``sock.recv``), which returns b"" on timeout
    or close."""
    got = b""
    while len(got) < n:
        more = read(n - len(got))
        assert more, f"timed out or closed after {got!r}"
        got += more
    return got
