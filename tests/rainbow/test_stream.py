"""The command stream: one table for both ends, robust decoding, socket transport, record and
replay."""

from __future__ import annotations

import struct

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.emulator.machine import RainbowMachine
from camlab88.emulator.rainbow import Rainbow, VideoMemory
from camlab88.emulator.rainbow.executor import Executor
from camlab88.protocols.rainbow import MouseEvent, RainbowClient, RainbowRefused, SocketTransport
from camlab88.protocols.rainbow.events import KeyEvent, TabletEvent, decode_events, encode_event
from camlab88.protocols.rainbow.recording import Recording
from camlab88.protocols.rainbow.stream import OPS_LIST, Decoder, StreamError, encode
from tests.support.rainbow_server import serving


def test_every_op_round_trips_through_the_decoder() -> None:
    d = Decoder()
    for op in OPS_LIST:
        args = tuple(range(len(op.fields)))
        blob = b"\x01\x02\x03" if op.blob else b""
        cmd = encode(op.name, *args, blob=blob)
        # split anywhere
        got = d.feed(cmd[:3]) + d.feed(cmd[3:])
        assert len(got) == 1 and got[0].op is op and got[0].args == args and got[0].blob == blob


@settings(max_examples=150, deadline=None)
@given(st.binary(max_size=200))
def test_garbage_never_crashes_the_device(data: bytes) -> None:
    ex = Executor(Rainbow())
    try:
        ex.feed(data)
    except StreamError as exc:
        assert "byte" in str(exc)
    if ex.decoder.error is not None:
        assert str(ex.decoder.error).startswith("byte ")
        with pytest.raises(StreamError):
            ex.feed(b"")  # a broken stream stays broken: no guessing at resynchronising
    # the device still works afterwards
    assert ex.handle(encode("create_cluster", 1, 10, 10))[0] == 0


_int = st.sampled_from([0, 1, 2, 3]) | st.integers(-300, 300) | st.integers(-(2**31), 2**31 - 1)


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(OPS_LIST), st.lists(_int, min_size=9, max_size=9), st.binary(max_size=64))
def test_random_calls_are_answered_never_raised(op, args, blob) -> None:
    """Any call, with any int32 arguments, on a device holding pads 1 (8-bit) and 3 (2-bit),
    cluster 2 and arc 1, gets a reply; the device keeps working."""
    r = Rainbow(memory=VideoMemory(512, 512))
    ex = Executor(r)
    r.create_pad(300, 200, 8, node=1)
    r.create_cluster(100, 100, node=2)
    r.create_pad(40, 30, 2, plane=3, node=3)
    r.map(0, 1, 10, 10, arc=1)
    frame = encode(op.name, *args[: len(op.fields)], blob=blob if op.blob else b"")
    status = ex.handle(frame)[0]
    assert status in (0, 1)
    assert ex.handle(encode("wait_frame"))[0] in (0, 1)
    # a node the random call cannot have made (it may have made one named by any argument:
    # hypothesis found create_pad(node=99, 1 x 1) taking node 99)
    fresh = next(n for n in range(90, 100) if n not in args)  # (ten ids, nine arguments)
    assert ex.handle(encode("create_cluster", fresh, 10, 10))[0] == 0


def test_unknown_opcode_names_byte_offset() -> None:
    d = Decoder()
    good = encode("destroy", 3)
    cmds = d.feed(good + struct.pack("<BI", 200, 0))
    assert [c.op.name for c in cmds] == ["destroy"]  # what came before is still carried out
    with pytest.raises(StreamError, match=f"byte {len(good)}: unknown opcode 200"):
        d.feed(b"")


def test_events_round_trip() -> None:
    evs = [MouseEvent(20, 5, 6, 3, 2, True), KeyEvent(40, "space", " ", True),
           TabletEvent(60, 1000, 2000, 512, 1, True), KeyEvent(80, "a", "", False)]
    assert decode_events(b"".join(encode_event(e) for e in evs)) == evs


def test_refusals_carry_the_reason() -> None:
    c = RainbowMachine().client
    with pytest.raises(RainbowRefused, match="cycle"):
        a = c.create_cluster(10, 10)
        b = c.create_cluster(10, 10)
        c.map(a, b)
        c.map(b, a)
    with pytest.raises(RainbowRefused, match="out of video memory"):
        for _ in range(100):
            c.create_pad(2048, 1024, 8)


def test_socket_transport_drives_the_same_device() -> None:
    device = Rainbow()
    port, t, _ = serving(1, device)
    c = RainbowClient(SocketTransport(port))
    try:
        p = c.create_pad(64, 32, 4, lut_page=1)
        c.map(0, p, 10, 20)
        c.set_lut(256, ["#ff0000"] * 16)
        c.rect(p, 0, 0, 64, 32, 5)
        assert c.get_pixels(p, 0, 0, 4, 2).tolist() == [[5] * 4] * 2
        with pytest.raises(RainbowRefused):
            c.line(p, 0, 0, 10, 10, 99)
        assert c.wait_frame() == (1, 20)
        assert c.hello() == {"screen_w": 768, "screen_h": 576, "lut_size": 4096,
                             "memory_w": 2048, "memory_h": 2048}
    finally:
        c.close()
        t.join(5)
    assert (device.peek()[20:52, 10:74] == [255, 0, 0]).all()


def test_record_and_replay(tmp_path) -> None:
    s = RainbowMachine(record=True)
    c = s.client
    p = c.create_pad(100, 100, 8)
    c.map(0, p, 5, 5)
    c.set_lut(0, [(i, 255 - i, i // 2) for i in range(256)])
    s.post(MouseEvent(0, 30, 40, 0))
    c.circle(p, 50, 50, 30, 77)
    c.wait_frame()
    s.post(MouseEvent(0, 31, 41, 2, 2, True))
    events = c.poll_events()
    assert [e.t_ms for e in events] == [0, 20]
    c.polygon(p, [(0, 0), (90, 10), (40, 80)], 200)
    c.wait_frame()
    path = tmp_path / "session.rec"
    s.recording.save(path)
    again = RainbowMachine()
    result = again.replay(Recording.load(path))
    assert result.mismatches == [] and result.commands > 5 and result.events == 2
    assert np.array_equal(again.frame(), s.frame())
    assert np.array_equal(again.device.memory.words, s.device.memory.words)


def test_bad_recording_names_the_line(tmp_path) -> None:
    path = tmp_path / "bad.rec"
    path.write_text("# camlab88 rainbow recording v1\n> 0100\nx 00\n")
    with pytest.raises(ValueError, match="bad.rec:3"):
        Recording.load(path)


def test_docs_op_table_matches_the_code() -> None:
    from pathlib import Path

    doc = (Path(__file__).resolve().parents[2] / "docs" / "rainbow.md").read_text()
    for op in OPS_LIST:
        fields = ", ".join(op.fields) or "—"
        assert f"| {op.code} | `{op.name}` | {fields} |" in doc, op.name


def test_keyboard_and_tablet_events_reach_the_program_in_order() -> None:
    s = RainbowMachine()
    s.post(KeyEvent(0, "a", "a", True))
    s.client.wait_frame()
    s.client.wait_frame()
    s.post(TabletEvent(0, 1200, 800, 700, 1, True))
    s.post(KeyEvent(0, "a", "", False))
    got = s.client.poll_events(limit=2)
    assert got == [KeyEvent(0, "a", "a", True), TabletEvent(40, 1200, 800, 700, 1, True)]
    assert s.client.poll_events() == [KeyEvent(40, "a", "", False)]
    assert s.client.poll_events() == []


def test_draining_the_event_queue_polls_again_while_a_reply_comes_back_full() -> None:
    s = RainbowMachine()
    keys = [KeyEvent(0, chr(ord("a") + i), "", True) for i in range(5)]
    for k in keys:
        s.post(k)
    assert list(s.client.drain_events(limit=2)) == keys  # replies of 2, 2 and 1 events
    assert list(s.client.drain_events(limit=2)) == []


def test_socket_garbage_gets_a_reason_then_the_next_client_is_served() -> None:
    import socket

    device = Rainbow()
    port, t, _ = serving(2, device)
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=5) as raw:
            raw.sendall(encode("create_cluster", 5, 10, 10) + b"\xfe\x00\x00\x00\x00")
            data = b""
            while chunk := raw.recv(4096):
                data += chunk
        from camlab88.protocols.rainbow.stream import split_reply

        status, _, rest = split_reply(data)
        assert status == 0
        status, msg, _ = split_reply(rest)
        assert status == 1 and b"byte 17: unknown opcode 254" in msg
        c = RainbowClient(SocketTransport(port))
        c._next_node = 6
        assert c.create_cluster(4, 4) == 6
        c.close()
    finally:
        t.join(5)
    # each connection is its own pad-library session: the first client's cluster 5 is gone
    assert set(device.graph.nodes) == {0, 6}
