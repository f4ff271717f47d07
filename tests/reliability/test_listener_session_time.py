"""No client holds a listener, however steadily it sends (docs/reliability.md, "Listeners"):
a client that trickles a byte a second (or a Rainbow frame a second) is never silent, so the
idle timeout never freed the line — 12 newcomers in 95 s were all refused. Now a client gives
way to the next newcomer once it has held the line ``session_time`` (default 180 s; line
time for the Sigma lines, measured here in virtual time), and each refused newcomer is told
how long at most it has to wait."""

from __future__ import annotations

import contextlib
import re
import socket
import time
from fractions import Fraction

from camlab88.protocols.link import LineSettings, SerialLine
from camlab88.protocols.link.transports import SESSION_TIME, TcpBridge
from camlab88.protocols.rainbow.stream import encode
from tests.support.rainbow_server import serving

STEP = Fraction(1, 100)  # s of line time a poll


def test_a_byte_a_second_client_gives_way_after_the_session_time() -> None:
    """The trial's attack, in virtual line time: a client sending one byte a second, a
    newcomer every 8 s. Before SESSION_TIME every newcomer is refused with the time left;
    the first to come after it gets the line, and the trickler is hung up on."""
    line = SerialLine(LineSettings())
    bridge = TcpBridge(0, endpoint=line.host, idle_timeout=60.0, session_time=SESSION_TIME)
    k = 0

    def step(n: int = 1) -> None:
        nonlocal k
        for _ in range(n):
            line.clock.advance_to(k * STEP)
            bridge.poll(timeout=0.0)
            k += 1

    refused: list[tuple[float, int]] = []  # (line time, seconds the refusal said) each
    admitted_at = None
    try:
        trickler = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
        step(5)
        second = 0
        while admitted_at is None and second < SESSION_TIME + 20:
            second += 1
            trickler.sendall(b"x")  # one byte every second of line time: never silent
            step(100)
            if second % 8:
                continue
            newcomer = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
            newcomer.settimeout(5)
            step(5)
            newcomer.setblocking(False)
            try:
                said = newcomer.recv(300)
            except BlockingIOError:  # nothing said and still open: it has the line
                admitted_at = float(k * STEP)
                newcomer.close()
                break
            newcomer.close()
            m = re.search(rb"in at most (\d+) s", said)
            assert m, said
            refused.append((float(k * STEP), int(m[1])))
        trickler.settimeout(5)
        assert trickler.recv(100) == b""  # hung up on
        trickler.close()
    finally:
        bridge.close()
    assert admitted_at is not None, refused
    assert SESSION_TIME <= admitted_at <= SESSION_TIME + 8 + 1, admitted_at
    assert len(refused) == int(SESSION_TIME // 8), refused
    for at, left in refused:  # each was told the truth, to the second
        assert abs((at + left) - SESSION_TIME) <= 2, (at, left)
    assert any(f"held the line for {SESSION_TIME:g} s" in e.detail for e in bridge.events)


def test_a_client_alone_keeps_the_line_past_the_session_time() -> None:
    """The session time is judged when someone else wants the line, not before."""
    line = SerialLine(LineSettings())
    bridge = TcpBridge(0, endpoint=line.host, session_time=2.0)
    try:
        with socket.create_connection(("127.0.0.1", bridge.port), timeout=5) as alone:
            for k in range(500):  # 5 s of line time, no newcomer
                line.clock.advance_to(k * STEP)
                bridge.poll(timeout=0.0)
            alone.setblocking(False)
            try:
                assert alone.recv(10) != b""
            except BlockingIOError:
                pass  # still connected, nothing said: as it should be
            assert bridge.connected
    finally:
        bridge.close()


def test_a_rainbow_program_sending_a_frame_a_tick_gives_way_after_the_session_time() -> None:
    """rainbow serve (wall time): a program sending a whole frame every 0.2 s, a newcomer
    every 0.5 s; with a 1.5 s session the newcomers are refused until it is over."""
    port, t, stats = serving(2, session_time=1.5, poll=0.05)
    began = time.monotonic()
    admitted = None
    with socket.create_connection(("127.0.0.1", port), timeout=5) as holder:
        holder.setblocking(False)
        n = 0
        while admitted is None and time.monotonic() - began < 10:
            with contextlib.suppress(OSError):
                holder.send(encode("create_cluster", 100 + n, 4, 4))
                while True:
                    if not holder.recv(4096):
                        break
            n += 1
            time.sleep(0.2)
            if n % 3:
                continue
            newcomer = socket.create_connection(("127.0.0.1", port), timeout=5)
            newcomer.settimeout(0.4)
            try:
                said = newcomer.recv(200)
            except TimeoutError:
                said = None  # kept open and silent: it is being served
            if said is None:
                admitted = time.monotonic() - began
            newcomer.close()
    t.join(5)
    assert admitted is not None and 1.5 <= admitted <= 10.0, (admitted, stats)  # loaded CI
    assert any("connected for" in d and "another program waited" in d
               for d in stats[0].dropped), stats
