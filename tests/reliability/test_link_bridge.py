"""`link echo --listen` and `sigma run --listen` (protocols.link.TcpBridge): a client never
receives bytes that belong to an earlier, disconnected one; resets and half-sent data only
end that connection. Real sockets on a 127.0.0.1 port the test opens; bounded loops on the
virtual clock."""

from __future__ import annotations

import socket
import struct
from fractions import Fraction

from protocols.link import LineSettings, SerialLine
from protocols.link.transports import TcpBridge

STEP = Fraction(1, 100)


def _step(bridge: TcpBridge, line: SerialLine, k: int) -> int:
    """One step of the echo device (as protocols.link.cli.run_echo does)."""
    line.clock.advance_to(k * STEP)
    bridge.poll(timeout=0.01)
    data = line.device.read()
    if data:
        line.device.write(data)
    return k + 1


def _drain(s: socket.socket) -> bytes:
    s.setblocking(False)
    out = b""
    while True:
        try:
            chunk = s.recv(4096)
        except BlockingIOError:
            return out
        if not chunk:
            return out
        out += chunk


def test_the_next_client_gets_only_its_own_echo() -> None:
    line = SerialLine(LineSettings())
    bridge = TcpBridge(0, endpoint=line.host)
    k = 0
    try:
        a = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
        a.sendall(b"A" * 200)  # 0.2 s of line time, still in flight when A leaves
        for _ in range(5):
            k = _step(bridge, line, k)
        a.close()
        b = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
        b.sendall(b"bee")
        got = b""
        for _ in range(200):  # 2 s of line time: A's echo has long drained, B's came back
            k = _step(bridge, line, k)
            got += _drain(b)
        b.close()
    finally:
        bridge.close()
    assert b"A" not in got and got == b"bee"


def test_a_reset_client_is_dropped_and_the_next_one_served() -> None:
    line = SerialLine(LineSettings())
    bridge = TcpBridge(0, endpoint=line.host)
    k = 0
    try:
        a = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
        a.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
        a.sendall(b"half")
        k = _step(bridge, line, k)
        a.close()  # RST
        for _ in range(50):  # the bridge notices the reset (the line keeps running)
            k = _step(bridge, line, k)
            if any(e.kind == "disconnected" for e in bridge.events):
                break
        c = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
        c.sendall(b"ok")
        got = b""
        for _ in range(200):
            k = _step(bridge, line, k)
            got += _drain(c)
        c.close()
    finally:
        bridge.close()
    assert got == b"ok"
    kinds = [e.kind for e in bridge.events]
    assert "refused" not in kinds
    assert kinds.count("connected") == 2 and "disconnected" in kinds


def test_a_second_client_is_refused_with_a_message() -> None:
    line = SerialLine(LineSettings())
    bridge = TcpBridge(0, endpoint=line.host)
    try:
        with socket.create_connection(("127.0.0.1", bridge.port), timeout=5) as a:
            _step(bridge, line, 0)
            with socket.create_connection(("127.0.0.1", bridge.port), timeout=5) as b:
                _step(bridge, line, 1)
                b.settimeout(5)
                assert b.recv(200).startswith(b"camlab88: another client is connected")
            a.sendall(b"x")
    finally:
        bridge.close()
    assert [e.kind for e in bridge.events][:2] == ["connected", "refused"]
