"""Servers (docs/reliability.md): `rainbow serve` survives resets, half frames, garbage and
idle clients, keeps per-connection state, and refuses a second program with a message.
Real sockets on 127.0.0.1 ports the test opens; every loop is bounded."""

from __future__ import annotations

import socket
import struct
import threading

from camlab88.emulator.rainbow.server import BUSY, ServerStats
from camlab88.protocols.rainbow import RainbowClient, SocketTransport
from camlab88.protocols.rainbow.stream import HEADER, REFUSED, encode
from tests.support.rainbow_server import serving


def _start(connections: int, **kw: float) -> tuple[int, threading.Thread, list[ServerStats]]:
    return serving(connections, poll=0.05, **kw)


def _reply(raw: socket.socket) -> tuple[int, bytes]:
    head = b""
    while len(head) < HEADER.size:
        chunk = raw.recv(HEADER.size - len(head))
        assert chunk, "server closed without replying"
        head += chunk
    status, n = HEADER.unpack(head)
    body = b""
    while len(body) < n:
        body += raw.recv(n - len(body))
    return status, body


def _hello_works(port: int) -> None:
    c = RainbowClient(SocketTransport(port, timeout=5))
    try:
        assert c.hello()["screen_w"] == 768
    finally:
        c.close()


def _reset(port: int) -> None:
    s = socket.create_connection(("127.0.0.1", port), timeout=5)
    s.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
    s.sendall(encode("hello")[:3])
    s.close()  # linger 0: the server sees ECONNRESET


def test_a_client_that_resets_does_not_kill_the_server() -> None:
    port, t, stats = _start(2)
    _reset(port)
    _hello_works(port)
    t.join(10)
    assert not t.is_alive() and stats[0].served == 2


def test_a_half_frame_stays_with_its_connection() -> None:
    port, t, stats = _start(2)
    with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
        s.sendall(encode("create_cluster", 5, 10, 10)[:7])  # half a frame, then gone
    _hello_works(port)  # a fresh decoder: the next client's first frame is read as its own
    t.join(10)
    assert stats[0].served == 2 and stats[0].dropped == ["closed by the client mid-frame"]


def test_garbage_offsets_count_from_the_connection_start() -> None:
    port, t, stats = _start(2)
    for _ in range(2):
        with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
            s.sendall(encode("hello") + b"\xfe\x00\x00\x00\x00")
            assert _reply(s)[0] != REFUSED
            status, why = _reply(s)
            assert status == REFUSED and why.startswith(b"byte 5:")
    t.join(10)
    assert stats[0].served == 2


def test_a_second_program_is_refused_with_a_message() -> None:
    port, t, stats = _start(1)
    with socket.create_connection(("127.0.0.1", port), timeout=5) as first:
        _hello_on(first)
        with socket.create_connection(("127.0.0.1", port), timeout=5) as second:
            status, why = _reply(second)
            assert status == REFUSED and why == BUSY
        _hello_on(first)  # the first program is still served
    t.join(10)
    assert stats[0].refused == 1 and stats[0].served == 1


def test_an_idle_program_gives_way_to_a_waiting_one() -> None:
    port, t, stats = _start(2, idle_timeout=0.0)
    with socket.create_connection(("127.0.0.1", port), timeout=5) as idle:
        _hello_on(idle)
        _hello_works(port)  # would block for ever behind the idle client before
        assert idle.recv(10) == b""  # the idle one was hung up on
    t.join(10)
    assert stats[0].served == 2 and any("idle" in d for d in stats[0].dropped)


def _hello_on(s: socket.socket) -> None:
    s.sendall(encode("hello"))
    assert _reply(s)[0] != REFUSED


def test_a_half_frame_left_hanging_is_hung_up_on() -> None:
    port, t, stats = _start(1, frame_timeout=0.2)
    with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
        s.sendall(encode("create_cluster", 5, 10, 10)[:7])
        assert s.recv(10) == b""  # the server hangs up by itself
    t.join(10)
    assert any("a frame unfinished" in d for d in stats[0].dropped)
