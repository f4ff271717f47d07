"""One client's bytes never reach the next (docs/reliability.md, "Listeners"): when a client
leaves, what it queued on the line and what was queued for it are dropped, and a new client
starts on an empty line and gets its own echo at once (in line time). `link echo --listen`
and `sigma run --listen` share the bridge; both are attacked here with a client that sends
30 KB (half a minute of a 9600-baud line) and leaves. Real sockets on 127.0.0.1 ports the
tests open; loops bounded on the virtual clock."""

from __future__ import annotations

import socket
from fractions import Fraction

from camlab88.emulator.harness.sigma_line import SigmaLineTarget
from camlab88.emulator.machine import SigmaMachine
from camlab88.protocols.link.transports import TcpBridge
from tests.support.listeners import EchoLine, drain

A_BYTES = bytes(range(0x41, 0x5B)) * 1200  # 31,200 bytes of A-Z: 32 s of line time


def test_the_next_client_gets_none_of_a_leaving_clients_bytes_and_its_echo_at_once() -> None:
    with EchoLine() as echo:
        a = echo.connect()
        a.sendall(A_BYTES)
        echo.step(200)  # 2 s of line time: A gets some of its echo
        assert drain(a), "A's own echo should have started"
        a.close()
        echo.step()
        b = echo.connect()
        b.sendall(b"bee 123")
        joined = echo.line.clock.exact
        got, when = b"", None
        for _ in range(300):  # 3 s of line time at most
            echo.step()
            got += drain(b)
            if got == b"bee 123":
                when = echo.line.clock.exact
                break
        b.close()
    assert got == b"bee 123", got[:80]
    # 7 characters go down and come back in 14 ms of line time; a few polls of settling
    assert when is not None and when - joined <= Fraction(1, 10), float(when - joined)


def _tick(target: SigmaLineTarget) -> None:
    target.handle_events([])
    target.tick()


def test_a_sigma_line_starts_each_client_on_an_empty_line() -> None:
    target = SigmaLineTarget(SigmaMachine("t5684"), None, "test")
    line = target.machine.line
    target.bridge = TcpBridge(0, endpoint=target.tap)
    fed = bytearray()
    term = target.machine.terminal
    feed = term.feed
    term.feed = lambda data: (fed.extend(data), feed(data))  # what the terminal got
    hello = b"\r\nhello from b"
    try:
        a = socket.create_connection(("127.0.0.1", target.bridge.port), timeout=5)
        a.sendall(A_BYTES)  # alpha text, 32 s of line time
        for _ in range(100):
            _tick(target)
        a.close()
        _tick(target)
        b = socket.create_connection(("127.0.0.1", target.bridge.port), timeout=5)
        b.sendall(hello)
        joined = line.clock.exact
        for _ in range(300):  # 3 s of line time at most
            _tick(target)
            if fed.endswith(hello):
                break
        when = line.clock.exact
        for _ in range(100):  # and nothing more arrives
            _tick(target)
        b.close()
    finally:
        target.bridge.close()
    assert fed.endswith(hello), bytes(fed[-40:])
    from_a = bytes(fed[:-len(hello)])
    # A's bytes, in order, stopped when B came: 1 s of line time and a tick is 970 bytes
    assert from_a == A_BYTES[:len(from_a)] and len(from_a) <= 972, len(from_a)
    assert when - joined <= Fraction(1, 10), float(when - joined)


def test_link_echo_listen_as_attacked_a_30_kb_client_then_a_second_one() -> None:
    """The trial's own steps: A sends 30 KB and closes; B connects 2 s later."""
    import time

    from tests.support.listeners import port_of, start, stop

    proc, first = start(["link", "echo", "--listen", "0"])
    try:
        port = port_of(first)
        with socket.create_connection(("127.0.0.1", port), timeout=5) as a:
            a.sendall(A_BYTES)
        time.sleep(2.0)
        with socket.create_connection(("127.0.0.1", port), timeout=5) as b:
            b.sendall(b"bee 123")
            b.settimeout(0.1)
            got, began = b"", time.monotonic()
            while len(got) < 7 and time.monotonic() - began < 3.0:
                try:
                    got += b.recv(100)
                except TimeoutError:
                    pass
            waited = time.monotonic() - began
    finally:
        stop(proc)
    assert got == b"bee 123", got[:80]
    assert waited < 1.0, waited  # its own echo at once (the trial: after 28.8 s)
