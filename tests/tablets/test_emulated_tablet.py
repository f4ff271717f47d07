"""The emulated tablet: real bytes on a pty that pyserial opens; it answers host queries."""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np
import pytest
import serial

from camlab88.emulator.host_input import PointerButton, PointerMove
from camlab88.emulator.tablet import EmulatedTablet, TabletView, demo_path, pointer_to_tablet
from camlab88.emulator.tablet.drive import PointerState
from camlab88.protocols.tablets import wacom4
from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.registry import PROTOCOL_NAMES, make_parser
from camlab88.protocols.tablets.summa import DEFAULT_MODEL as SUMMA_MODEL
from camlab88.protocols.tablets.wacom4 import DEFAULT_MODEL as WACOM_MODEL
from tests.tablets.helpers import HANG_GUARD


def _read(port: serial.Serial, n: int) -> bytes:
    got = bytearray()
    deadline = time.monotonic() + HANG_GUARD
    while len(got) < n and time.monotonic() < deadline:
        got += port.read(n - len(got))
    return bytes(got)


def _ask(tablet: EmulatedTablet, host: serial.Serial, command: bytes, until: bytes) -> bytes:
    host.write(command)
    got = bytearray()
    deadline = time.monotonic() + HANG_GUARD
    while until not in got and time.monotonic() < deadline:
        tablet.service(0.001)
        got += host.read(64)
    return bytes(got)


def _command(tablet: EmulatedTablet, host: serial.Serial, command: bytes) -> None:
    """Send a host command and wait until the tablet has handled it."""
    host.write(command)
    seen = len(tablet.commands)
    deadline = time.monotonic() + HANG_GUARD
    while len(tablet.commands) == seen and time.monotonic() < deadline:
        tablet.service(0.001)


@pytest.fixture
def host_for():
    opened = []

    def make(protocol: str, options=None):
        tablet = EmulatedTablet(protocol, options)
        host = serial.Serial(tablet.slave_path, 9600, timeout=0.05)
        opened.append((tablet, host))
        return tablet, host

    yield make
    for tablet, host in opened:
        host.close()
        tablet.close()


@pytest.mark.parametrize("protocol", PROTOCOL_NAMES)
def test_pointer_events_arrive_as_protocol_bytes(host_for, protocol: str) -> None:
    tablet, host = host_for(protocol)
    parser = make_parser(protocol)
    size = (641, 481)
    events = [pointer_to_tablet(x, 240, size, tablet.model, b, tool="puck"
                                if protocol in ("bitpad1", "bitpad2", "calcomp") else "pen")
              for x, b in ((0, 0), (320, 1), (640, 1), (640, 0))]
    sent = b"".join(tablet.send(e) for e in events)
    assert parser.feed(_read(host, len(sent))) == events
    assert events[2].x == tablet.model.max_x  # right edge of the window = tablet max X


def test_default_emulated_tablet_is_summagraphics(host_for) -> None:
    tablet, _ = host_for("summa-mm")
    assert EmulatedTablet.__init__.__defaults__[0] == "summa-mm"
    assert tablet.line.describe() == "9600 8O1, flow XOFF to the tablet"


def test_wacom_identification_queries(host_for) -> None:
    tablet, host = host_for("wacom4")
    reply = _ask(tablet, host, b"~#", b"\r")
    assert reply.decode().strip() == "~#UD-1212-R00 V1.4-4"  # the ledger's model string
    assert wacom4.parse_model_reply(reply.decode().strip()).code == "UD"
    reply = _ask(tablet, host, b"~C\r", b"\r")
    assert wacom4.parse_coords_reply(reply.decode().strip()) == (15240, 15240)
    reply = _ask(tablet, host, b"~R\r", b"\r")
    settings = wacom4.parse_settings_reply(reply.decode().strip())
    assert settings.command_set == "wacom4" and settings.res_x == 1270
    _ask(tablet, host, b"SP\r", b"")
    assert tablet.send(TabletEvent(1, 1)) == b""  # stopped
    _ask(tablet, host, b"ST\r", b"")
    assert tablet.send(TabletEvent(1, 1)) != b""


def test_summa_config_and_prompt_mode(host_for) -> None:
    tablet, host = host_for("summa-mm")
    reply = _ask(tablet, host, b"a", b"")
    deadline = time.monotonic() + HANG_GUARD
    while len(reply) < 5 and time.monotonic() < deadline:
        tablet.service(0.001)
        reply += host.read(5)
    (config,) = make_parser("summa-mm").feed(reply)
    assert (config.x, config.y) == (tablet.model.max_x, tablet.model.max_y)
    _ask(tablet, host, b"B", b"")  # prompt mode: silent until "P"
    assert tablet.send(TabletEvent(5, 5)) == b""
    _ask(tablet, host, b"P", b"")
    assert tablet.send(TabletEvent(5, 5)) != b""
    assert tablet.send(TabletEvent(5, 5)) == b""


def test_pointer_state_and_origin_flip() -> None:
    state = PointerState()
    state.apply(PointerMove(10, 20, frozenset()))
    state.apply(PointerButton(10, 20, 1, True))
    state.apply(PointerButton(10, 20, 3, True))
    assert state.mask == 0b011
    state.apply(PointerButton(10, 20, 1, False))
    assert state.mask == 0b010
    lower_left = replace(SUMMA_MODEL, origin="lower-left")
    top = pointer_to_tablet(0, 0, (101, 101), lower_left, 0)
    assert (top.x, top.y) == (0, SUMMA_MODEL.max_y)  # lower-left origin: window top = max Y
    top = pointer_to_tablet(0, 0, (101, 101), WACOM_MODEL, 0)
    assert (top.x, top.y) == (0, 0)


def test_view_draws_what_was_decoded() -> None:
    view = TabletView(SUMMA_MODEL, width=200)
    for fx, fy, b in demo_path(120):
        w, h = view.size
        view.add(pointer_to_tablet(fx * (w - 1), fy * (h - 1), view.size, SUMMA_MODEL, b))
    frame = view.frame()
    assert frame.shape == (view.size[1], view.size[0], 3)
    ink = np.all(frame == (20, 30, 120), axis=2)
    assert ink.sum() > 100
    ys, xs = np.nonzero(ink)
    assert xs.min() < 0.35 * view.size[0] and xs.max() > 0.8 * view.size[0]


def test_unplug_is_seen_by_the_host(host_for) -> None:
    tablet, host = host_for("calcomp")
    tablet.send(TabletEvent(1, 2, tool="puck"))
    assert _read(host, 6)
    tablet.close()
    with pytest.raises(serial.SerialException):
        deadline = time.monotonic() + HANG_GUARD
        while time.monotonic() < deadline:
            host.read(1)


def test_view_golden_after_demo_through_the_protocol() -> None:
    """The demo stroke, encoded as Summagraphics bytes and decoded again, drawn on the view."""
    from pathlib import Path

    from camlab88.protocols.tablets.registry import make_encoder
    from tests.support.golden import assert_matches_golden

    enc, parser = make_encoder("summa-mm"), make_parser("summa-mm")
    view = TabletView(SUMMA_MODEL, width=320)
    w, h = view.size
    data = b"".join(enc.encode(pointer_to_tablet(fx * (w - 1), fy * (h - 1), view.size,
                                                 SUMMA_MODEL, b)) for fx, fy, b in demo_path())
    for event in parser.feed(data):
        view.add(event)
    golden = Path(__file__).resolve().parents[1] / "data" / "tablets" / "golden_demo_view.png"
    assert_matches_golden(view.frame(), golden)


def test_chords_and_impossible_events_never_crash_the_device(host_for) -> None:
    tablet, host = host_for("summa-mm")
    data = tablet.send(TabletEvent(10, 10, True, 0b011))  # left + right: code format
    assert make_parser("summa-mm").feed(data)[0].buttons == 0b001  # lowest button reported
    wacom, _ = host_for("wacom4")
    assert wacom.send(TabletEvent(10, 10, True, 0x10, 5, tool="pen")) == b""
    assert wacom.refused == 1 and "buttons" in wacom.last_refusal
    assert wacom.send(TabletEvent(10, 10, True, 0b001, 5)) != b""  # and it carries on


def test_summa_tablet_honours_the_origin_command_the_host_sends(host_for) -> None:
    from camlab88.protocols.tablets.line_setup import line_setup

    init = b"".join(step.data for step in line_setup("summa-mm").init)
    assert b"b" in init  # our start-up asks for the origin upper-left ...
    assert make_parser("summa-mm").model.origin == "upper-left"  # ... and decodes with it
    tablet, host = host_for("summa-mm")
    assert tablet.model.origin == "lower-left"  # power-on origin
    top_left = pointer_to_tablet(0, 0, (101, 101), tablet.model, 0)
    assert top_left.y == tablet.model.max_y
    _command(tablet, host, b"b")
    assert tablet.model.origin == "upper-left"
    data = tablet.send(pointer_to_tablet(0, 0, (101, 101), tablet.model, 0))
    (event,) = make_parser("summa-mm").feed(data)
    assert (event.x, event.y) == (0, 0)  # the window's top-left is the tablet's origin now
    _command(tablet, host, b"\x00")  # reset: power-on origin again
    assert tablet.model.origin == "lower-left"


def test_wacom_middle_button_alone_reaches_the_host_as_the_barrel(host_for) -> None:
    tablet, host = host_for("wacom4")
    data = tablet.send(TabletEvent(100, 200, True, 0b100, 0))  # middle mouse button only
    assert tablet.refused == 0 and data
    (event,) = make_parser("wacom4").feed(data)
    assert (event.tool, event.buttons) == ("pen", 0b010)  # not the eraser, not dropped
