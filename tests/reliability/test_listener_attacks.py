"""Seeded attacks on the listeners, each followed by an honest client that must be served
at once and see nothing of the attacker (docs/reliability.md, "Listeners"). Fixed seeds;
the line runs on the virtual clock; real sockets on 127.0.0.1 ports the tests open; every
wait bounded (the whole file takes seconds)."""

from __future__ import annotations

import random
import socket
import struct
import time
from fractions import Fraction

import pytest

from camlab88.protocols.link import LineSettings, SerialLine
from camlab88.protocols.link.transports import TcpBridge
from camlab88.protocols.rainbow import RainbowClient, SocketTransport
from camlab88.protocols.rainbow.stream import encode
from tests.support.listeners import drain, echo_step
from tests.support.rainbow_server import serving

ROUNDS = 12


def _leave(s: socket.socket, how: str) -> None:
    if how == "reset":
        s.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
    elif how == "half-close":
        s.shutdown(socket.SHUT_WR)
    s.close()


def _attack_line(rng: random.Random, port: int) -> socket.socket | None:
    """One attacker: random bytes (XOFF and XON among them), random amount, left one of
    three ways; sometimes it stays connected, silent (returned, to be closed later)."""
    s = socket.create_connection(("127.0.0.1", port), timeout=5)
    s.setblocking(False)
    data = bytes(rng.choice(b"AZaz09\x11\x13\r\n+-*/") for _ in range(rng.choice([1, 200,
                                                                                  5000, 40000])))
    try:
        s.send(data)
    except BlockingIOError:
        pass
    if rng.random() < 0.2:
        return s
    _leave(s, rng.choice(["close", "reset", "half-close"]))
    return None


@pytest.mark.parametrize("seed", [2026, 27, 3])
def test_an_echo_line_serves_each_honest_client_cleanly_after_random_attackers(
        seed: int) -> None:
    rng = random.Random(seed)
    line = SerialLine(LineSettings())
    bridge = TcpBridge(0, endpoint=line.host)
    k, lingering = 0, None
    try:
        for r in range(ROUNDS):
            lingering = _attack_line(rng, bridge.port)
            for _ in range(rng.choice([1, 5, 50])):
                k = echo_step(bridge, line, k)
            if lingering is not None:  # a silent attacker holds the line until it leaves
                _leave(lingering, "close")
                lingering = None
            k = echo_step(bridge, line, k)
            honest = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
            word = f"honest {r} ".encode() * 3
            honest.sendall(word)
            joined, got = line.clock.exact, b""
            for _ in range(100):  # 1 s of line time at most
                k = echo_step(bridge, line, k)
                got += drain(honest)
                if len(got) >= len(word):
                    break
            waited = line.clock.exact - joined
            _leave(honest, "close")
            k = echo_step(bridge, line, k)
            assert got == word, (r, got[:60])
            assert waited <= Fraction(1, 5), (r, float(waited))
    finally:
        bridge.close()


def _attack_rainbow(rng: random.Random, port: int) -> None:
    s = socket.create_connection(("127.0.0.1", port), timeout=5)
    kind = rng.choice(["garbage", "half", "reset", "pads", "trickle"])
    if kind == "garbage":
        s.sendall(bytes(rng.randrange(256) for _ in range(rng.randrange(1, 64))))
    elif kind == "half":
        s.sendall(encode("create_cluster", 77, 10, 10)[:rng.randrange(1, 19)])
    elif kind == "pads":  # a whole session's worth of state, left behind
        s.sendall(encode("create_cluster", 77, 10, 10) + encode("create_pad", 78, 8, 8, 1, 0, 0))
        time.sleep(0.05)
    elif kind == "trickle":
        for b in encode("create_cluster", 77, 10, 10)[:5]:
            s.sendall(bytes([b]))
            time.sleep(0.02)
    _leave(s, "reset" if kind == "reset" or rng.random() < 0.3 else "close")


@pytest.mark.parametrize("seed", [2026, 9])
def test_rainbow_serve_serves_each_honest_program_fresh_after_random_attackers(
        seed: int) -> None:
    rng = random.Random(seed)
    port, t, stats = serving(2 * ROUNDS, frame_timeout=0.5, poll=0.02)
    for r in range(ROUNDS):
        _attack_rainbow(rng, port)
        began = time.monotonic()
        c = RainbowClient(SocketTransport(port, timeout=5))
        try:
            assert c.hello()["screen_w"] == 768
            c._next_node = 77
            assert c.create_cluster(4, 4) == 77, r  # nothing of the attacker's session
        finally:
            c.close()
        assert time.monotonic() - began < 2.0, r
    t.join(10)
    assert stats and stats[0].served == 2 * ROUNDS and stats[0].refused == 0
