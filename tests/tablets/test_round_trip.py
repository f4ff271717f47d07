"""events -> encoder -> pty -> pyserial -> parser -> the same events, for every protocol."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from camlab88.protocols.tablets import calcomp, summa, wacom4
from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.registry import make_encoder, make_parser

SETTINGS = settings(max_examples=25, deadline=None,
                    suppress_health_check=[HealthCheck.function_scoped_fixture])
# Binary parsers reject coordinates beyond the model's maximum (line-noise phantoms), so the
# events drawn stay on the tablet.
wacom_coord = st.integers(0, min(wacom4.DEFAULT_MODEL.max_x, wacom4.DEFAULT_MODEL.max_y))
summa_coord = st.integers(0, summa.DEFAULT_MODEL.max_x)
calcomp_coord = st.integers(0, calcomp.DEFAULT_MODEL.max_x)


@st.composite
def wacom_events(draw, tilt: bool = False) -> TabletEvent:
    tool = draw(st.sampled_from(["pen", "eraser", "puck"]))
    prox = draw(st.booleans())
    buttons = draw(st.integers(0, 15))
    pressure = None
    if tool == "pen":
        buttons &= ~0x04  # the eraser bit would make it the eraser
    elif tool == "eraser":
        buttons |= 0x04
    if tool != "puck" and prox:
        pressure = draw(st.integers(0, 255))
    tx = draw(st.integers(-64, 63)) if tilt else None
    ty = draw(st.integers(-64, 63)) if tilt else None
    return TabletEvent(draw(wacom_coord), draw(wacom_coord), prox, buttons, pressure, tx, ty,
                       tool)


one_button = st.sampled_from([0, 1, 2, 4, 8, 16, 32, 64])


@st.composite
def summa_events(draw, flair: bool = False) -> TabletEvent:
    tool = draw(st.sampled_from(["pen", "puck"])) if flair else "pen"
    pressure = draw(st.integers(0, 511)) if flair else None
    return TabletEvent(draw(summa_coord), draw(summa_coord),
                       draw(st.booleans()), draw(one_button), pressure, None, None, tool)


@st.composite
def bitpad2_events(draw) -> TabletEvent:
    prox = draw(st.booleans())
    buttons = draw(st.sampled_from([0, 1, 2, 4, 8, 16, 32, 64, 128])) if prox else 0
    return TabletEvent(draw(st.integers(0, 9999)), draw(st.integers(0, 9999)), prox, buttons,
                       tool="puck")


@st.composite
def bitpad1_events(draw) -> TabletEvent:
    return TabletEvent(draw(st.integers(0, 9999)), draw(st.integers(0, 9999)), True,
                       draw(st.integers(0, 15)), tool="puck")


@st.composite
def calcomp_events(draw) -> TabletEvent:
    return TabletEvent(draw(calcomp_coord), draw(calcomp_coord), draw(st.booleans()),
                       draw(st.integers(0, 15)), tool="puck")


def _round_trip(pair, name: str, events: list[TabletEvent], options=None) -> None:
    enc = make_encoder(name, options)
    parser = make_parser(name, options)
    data = b"".join(enc.encode(e) for e in events)
    assert pair.through(parser, data) == events


@pytest.mark.parametrize(("name", "strategy", "options"), [
    ("wacom4", wacom_events(), None),
    ("wacom4", wacom_events(tilt=True), {"tilt": "1"}),
    ("summa-mm", summa_events(), None),
    ("summa-flair", summa_events(flair=True), None),
    ("bitpad2", bitpad2_events(), None),
    ("bitpad1", bitpad1_events(), None),
    ("calcomp", calcomp_events(), None),
], ids=["wacom4", "wacom4-tilt", "summa-mm", "summa-flair", "bitpad2", "bitpad1", "calcomp"])
@SETTINGS
@given(data=st.data())
def test_events_come_back_through_a_pty(shared_pty, name, strategy, options, data) -> None:
    events = data.draw(st.lists(strategy, min_size=1, max_size=6))
    _round_trip(shared_pty, name, events, options)


STRATEGIES = {"wacom4": wacom_events(), "summa-mm": summa_events(),
              "bitpad1": bitpad1_events(), "bitpad2": bitpad2_events(),
              "calcomp": calcomp_events()}


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(sorted(STRATEGIES)), st.data())
def test_any_split_and_leading_junk_decode_the_same(name, data) -> None:
    events = data.draw(st.lists(STRATEGIES[name], min_size=1, max_size=5))
    stream = b"".join(make_encoder(name).encode(e) for e in events)
    junk = data.draw(st.binary(max_size=8).map(lambda b: bytes(c & 0x7F for c in b)))
    if name.startswith("bitpad"):
        junk += b"\r\n"  # ASCII formats resync on the line end
    cuts = sorted(data.draw(st.lists(st.integers(0, len(stream)), max_size=6)))
    parser = make_parser(name)
    out = parser.feed(junk)
    whole = junk + stream
    prev = len(junk)
    for cut in cuts:
        out += parser.feed(whole[prev : len(junk) + cut])
        prev = len(junk) + cut
    out += parser.feed(whole[prev:])
    assert out == events  # the junk (bit 7 clear, under a report's length) adds nothing
