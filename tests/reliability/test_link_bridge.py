"""`link echo --listen` and `sigma run --listen` (protocols.link.TcpBridge): a client never
receives bytes that belong to an earlier, disconnected one; resets and half-sent data only
end that connection. Real sockets on a 127.0.0.1 port the test opens; bounded loops on the
virtual clock."""

from __future__ import annotations

import socket
import struct

from tests.support.listeners import EchoLine, drain

# real sockets: each step gives the kernel a moment to pass the bytes on
WAIT = 0.01


def test_the_next_client_gets_only_its_own_echo() -> None:
    with EchoLine(WAIT) as echo:
        a = echo.connect()
        a.sendall(b"A" * 200)  # 0.2 s of line time, still in flight when A leaves
        echo.step(5)
        a.close()
        b = echo.connect()
        b.sendall(b"bee")
        got = b""
        for _ in range(200):  # 2 s of line time: A's echo has long drained, B's came back
            echo.step()
            got += drain(b)
        b.close()
    assert b"A" not in got and got == b"bee"


def test_a_reset_client_is_dropped_and_the_next_one_served() -> None:
    with EchoLine(WAIT) as echo:
        a = echo.connect()
        a.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
        a.sendall(b"half")
        echo.step()
        a.close()  # RST
        for _ in range(50):  # the bridge notices the reset (the line keeps running)
            echo.step()
            if any(e.kind == "disconnected" for e in echo.bridge.events):
                break
        c = echo.connect()
        c.sendall(b"ok")
        got = b""
        for _ in range(200):
            echo.step()
            got += drain(c)
        c.close()
    assert got == b"ok"
    kinds = [e.kind for e in echo.bridge.events]
    assert "refused" not in kinds
    assert kinds.count("connected") == 2 and "disconnected" in kinds


def test_a_second_client_is_refused_with_a_message() -> None:
    with EchoLine(WAIT) as echo:
        with echo.connect() as a:
            echo.step()
            with echo.connect() as b:
                echo.step()
                b.settimeout(5)
                assert b.recv(200).startswith(b"camlab88: another client is connected")
            a.sendall(b"x")
    assert [e.kind for e in echo.bridge.events][:2] == ["connected", "refused"]
