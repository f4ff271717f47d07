"""Line noise never crashes a parser, and damaged descriptors fail with a located error."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.hid_decode import HidReportError, PenDecoder
from camlab88.protocols.tablets.hid_descriptor import HidDescriptorError, parse_descriptor
from camlab88.protocols.tablets.registry import PROTOCOL_NAMES, make_encoder, make_parser
from tests.tablets.helpers import DIGIMEND, load_descriptor

H610 = load_descriptor(DIGIMEND / "Huion_H610/rd/original0.txt")


@settings(max_examples=80, deadline=None)
@given(st.sampled_from(PROTOCOL_NAMES), st.binary(max_size=300), st.booleans())
def test_parsers_survive_noise_and_recover(name, noise, parmrk) -> None:
    parser = make_parser(name, parmrk=parmrk)
    # noise, then a line end for the ASCII formats (they resync on it) -- whatever that made
    resync = b"\r\n" if name.startswith("bitpad") else b""
    parser.feed(noise + resync)
    parser.flush()
    # after it, good reports decode to exactly themselves: nothing lost, nothing extra
    event = TabletEvent(100, 200, True, 1, 50 if name == "wacom4" else None,
                        tool="puck" if name in ("bitpad1", "bitpad2", "calcomp") else "pen")
    good = make_encoder(name).encode(event)
    assert parser.feed(good * 2) == [event, event]


def _event(name: str, x: int, y: int) -> TabletEvent:
    return TabletEvent(x, y, True, 1, 50 if name == "wacom4" else None,
                       tool="puck" if name == "calcomp" else "pen")


@pytest.mark.parametrize("name", ["summa-mm", "wacom4", "calcomp"])
@pytest.mark.parametrize("cut", [1, 2, 3])
def test_cut_packet_completed_by_noise_is_no_phantom(name, cut) -> None:
    """A packet loses its tail on the line; non-sync noise (bit 7 clear) fills it to length.
    It frames like a packet, but its coordinates are off the tablet: rejected."""
    enc = make_encoder(name)
    first, cut_short, last = (_event(name, *xy) for xy in ((100, 200), (300, 400), (500, 600)))
    damaged = enc.encode(cut_short)[:cut]
    noise = b"\x7f" * (len(enc.encode(cut_short)) - cut)
    parser = make_parser(name)
    out = parser.feed(enc.encode(first) + damaged + noise + enc.encode(last))
    assert out == [first, last]
    assert parser.stats.bad_packets == 1


def test_summa_noise_without_the_absolute_sign_bits_is_no_phantom() -> None:
    # 0x81 looks like a sync byte, and 4 small bytes make in-range coordinates (129, 129):
    # only the sign bits (0x18), which absolute mode always sets, tell it from a report.
    enc = make_encoder("summa-mm")
    event = _event("summa-mm", 100, 200)
    parser = make_parser("summa-mm")
    out = parser.feed(enc.encode(event) + b"\x81\x01\x01\x01\x01" + enc.encode(event))
    assert out == [event, event] and parser.stats.bad_packets == 1


def test_size_options_widen_the_accepted_range() -> None:
    big = TabletEvent(9000, 7000, True, 0)
    data = make_encoder("summa-mm").encode(big)
    assert make_parser("summa-mm").feed(data) == []  # beyond the 12x12 default: rejected
    assert make_parser("summa-mm", {"max_x": "9000", "max_y": "9000"}).feed(data) == [big]


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


def test_bitpad2_configuration_reply_is_a_reply_not_a_bad_report() -> None:
    from camlab88.protocols.tablets.ascii_line import apply_parity

    parser = make_parser("bitpad2")
    reply = apply_parity(b"MM1103 BIT PAD II by Summagraphics Version 2.1\r\n", "E")
    event = TabletEvent(100, 200, True, 1, tool="puck")
    assert parser.feed(reply + make_encoder("bitpad2").encode(event)) == [event]
    (got,) = parser.take_replies()
    assert got.text.startswith("MM1103 BIT PAD II") and parser.stats.bad_packets == 0
