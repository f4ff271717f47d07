"""Line noise never crashes a parser, and damaged descriptors fail with a located error."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from protocols.tablets.events import TabletEvent
from protocols.tablets.hid_decode import HidReportError, PenDecoder
from protocols.tablets.hid_descriptor import HidDescriptorError, parse_descriptor
from protocols.tablets.registry import PROTOCOL_NAMES, make_encoder, make_parser
from tests.tablets.helpers import DIGIMEND, load_descriptor

H610 = load_descriptor(DIGIMEND / "Huion_H610/rd/original0.txt")


@settings(max_examples=80, deadline=None)
@given(st.sampled_from(PROTOCOL_NAMES), st.binary(max_size=300), st.booleans())
def test_parsers_survive_noise_and_recover(name, noise, parmrk) -> None:
    parser = make_parser(name, parmrk=parmrk)
    parser.feed(noise)
    parser.flush()
    # after the noise (and a line end for the ASCII formats) a good report decodes
    event = TabletEvent(100, 200, True, 1, 50 if name == "wacom4" else None,
                        tool="puck" if name in ("bitpad1", "bitpad2", "calcomp") else "pen")
    good = make_encoder(name).encode(event)
    resync = b"\r\n" if name.startswith("bitpad") else b""
    out = parser.feed(resync + good * 2)
    assert out and out[-1] == event


@settings(max_examples=80, deadline=None)
@given(st.binary(max_size=200))
def test_random_descriptors_fail_cleanly(data) -> None:
    try:
        parse_descriptor(data, "fuzz.rd")
    except HidDescriptorError as exc:
        assert str(exc).startswith("fuzz.rd: byte ")


@settings(max_examples=80, deadline=None)
@given(st.binary(min_size=1, max_size=20))
def test_random_reports_fail_cleanly(report) -> None:
    try:
        PenDecoder(H610).decode(report)
    except HidReportError as exc:
        assert "report" in str(exc)
