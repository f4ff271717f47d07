"""TCP on loopback and pyserial URLs, joined to a SerialLine end."""

from __future__ import annotations

import socket

from camlab88.protocols.link import SerialLine
from camlab88.protocols.link.transports import BUSY, SerialUrlBridge, TcpBridge
from tests.link.exactly import read_exactly


def pump(line: SerialLine, bridge, want: int, endpoint_read) -> bytes:
    got = b""
    for _ in range(200):
        bridge.poll(timeout=0.05)
        line.clock.advance(0.04)
        got += endpoint_read()
        if len(got) >= want:
            break
    return got


def test_tcp_client_talks_to_the_device_end_and_may_reconnect() -> None:
    line = SerialLine()
    with TcpBridge(0, endpoint=line.host) as bridge:
        assert bridge.host == "127.0.0.1" and bridge.port > 0
        client = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
        client.sendall(b"+-*/DRAW")
        assert pump(line, bridge, 8, line.device.read) == b"+-*/DRAW"
        assert [e.kind for e in bridge.events] == ["connected"]
        # a second client is turned away while the first is connected
        second = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
        line.device.write(b"ok")
        line.clock.advance(1)
        bridge.poll(timeout=0.2)
        assert read_exactly(client.recv, 2) == b"ok"
        assert read_exactly(second.recv, len(BUSY)) == BUSY  # told why, then closed
        assert second.recv(10) == b""
        second.close()
        assert "refused" in [e.kind for e in bridge.events]
        client.close()
        for _ in range(50):
            bridge.poll(timeout=0.05)
            if not bridge.connected:
                break
        assert not bridge.connected and bridge.events[-1].kind == "disconnected"
        # nobody connected: bytes reaching the end are dropped and counted, not an error
        line.device.write(b"lost")
        line.clock.advance(1)
        assert bridge.poll().dropped == 4
        again = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
        again.sendall(b"more")
        assert pump(line, bridge, 4, line.device.read) == b"more"
        line.device.write(b"back")
        line.clock.advance(1)
        bridge.poll()
        assert read_exactly(again.recv, 4) == b"back"
        again.close()


def test_outside_bytes_enter_at_the_poll_time_and_are_paced() -> None:
    line = SerialLine()
    with TcpBridge(0, endpoint=line.host) as bridge:
        client = socket.create_connection(("127.0.0.1", bridge.port), timeout=5)
        line.clock.advance_to(2)
        client.sendall(b"x" * 96)
        got = 0
        while got < 96:
            got += bridge.poll(timeout=1).inbound  # all while the clock stands at 2 s
        runs = line.device.read_timed(until=10)
        assert runs[-1][0] == 2 + 96 / 960
        client.close()


def test_serial_url_loop_round_trip() -> None:
    line = SerialLine()
    with SerialUrlBridge("loop://", line.settings, endpoint=line.host) as bridge:
        assert bridge.connected
        line.device.write(b"echo me")  # device -> host end -> loop:// -> back in at host end
        got = pump(line, bridge, 7, line.device.read)
        assert got == b"echo me"
        assert bridge.bytes_in == 7 and bridge.bytes_out == 7


def test_serial_url_that_cannot_open_is_reported_not_raised() -> None:
    line = SerialLine()
    bridge = SerialUrlBridge("/dev/does-not-exist-camlab88", endpoint=line.host)
    assert not bridge.connected
    assert bridge.events[-1].kind == "error" and "does-not-exist" in bridge.events[-1].detail
    line.device.write(b"x")
    line.clock.advance(1)
    assert bridge.poll().dropped == 1
    bridge.close()


def test_serial_url_socket_to_a_tcp_bridge() -> None:
    """Two lines joined by pyserial's socket:// URL to a TcpBridge: a cable between devices."""
    a, b = SerialLine(), SerialLine()
    with TcpBridge(0, endpoint=a.host) as server:
        server.poll()
        with SerialUrlBridge(f"socket://127.0.0.1:{server.port}", endpoint=b.device) as url:
            b.host.write(b"across")  # arrives at b.device, leaves by socket://, enters a.host
            got = b""
            for _ in range(200):
                b.clock.advance(0.04)
                a.clock.advance(0.04)
                url.poll(timeout=0.02)
                server.poll(timeout=0.02)
                got += a.device.read()
                if len(got) >= 6:
                    break
            assert got == b"across"


def test_serial_url_reconnects_after_the_far_end_hangs_up() -> None:
    a, b = SerialLine(), SerialLine()
    with TcpBridge(0, endpoint=a.host) as server:
        url = SerialUrlBridge(f"socket://127.0.0.1:{server.port}", endpoint=b.device)
        server.poll(timeout=0.5)
        assert server.connected
        server.disconnect()
        kinds: list[str] = []
        for _ in range(3 * SerialUrlBridge.RETRY_POLLS):
            kinds += [e.kind for e in url.poll(timeout=0.01).events]
            server.poll(timeout=0.01)
            if kinds[-1:] == ["connected"] and "disconnected" in kinds:
                break
        assert kinds == ["connected", "disconnected", "connected"]
        assert url.connected and server.connected
        url.close()
