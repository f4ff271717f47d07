"""camlab88.protocols.sigma: the one order table drives encoder and decoder; framing and formats."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.protocols.sigma import (
    ORDERS,
    AgsEnd,
    AgsEscape,
    AgsPoints,
    AlphaText,
    Decoder,
    Dots,
    DotsEnd,
    Encoder,
    GraphicsFlag,
    GraphicsText,
    Order,
    Point,
    format_report,
    parse_report,
)
from camlab88.protocols.sigma.abbreviated import AgsPointEncoder, encode_points
from camlab88.protocols.sigma.orders import Kind


def _sample_args(spec) -> tuple[int, ...]:
    return tuple(f.maximum - (k % 3) for k, f in enumerate(spec.fields))


@pytest.mark.parametrize("spec", ORDERS, ids=[o.code for o in ORDERS])
def test_every_order_round_trips_through_the_table(spec) -> None:
    e = Encoder()
    args = _sample_args(spec)
    data = e.order(spec.code, *args)
    assert data[:2] == spec.code.encode()
    assert len(data) == 2 + sum(f.width for f in spec.fields)
    assert getattr(Encoder, spec.name)  # every order has a named encoder method
    cmds = Decoder().feed(b"+-*/" + data)
    assert cmds[0] == GraphicsFlag()
    assert cmds[1] == Order(spec.code, args)


def test_named_methods_format_fields() -> None:
    e = Encoder()
    assert e.lut(3, 15, 0, 7) == b"JG3F070"
    assert e.dash_mask(0xF0F0) == b"DLF0F0"
    assert e.sequence_length(0) + e.xon_char(17) + e.xoff_char(19) == b"DD000DG017DF019"
    assert e.prompt_char(999) + e.cursor_shape(1) == b"HE999CK1"
    assert e.reset() == b"HH" + bytes(10)
    with pytest.raises(ValueError, match="colour=16"):
        e.order("HI", 16)
    with pytest.raises(ValueError, match="unknown Sigma order"):
        e.order("QQ")


def test_decimal_pairs_are_excess_100_and_follow_io() -> None:
    e = Encoder()
    assert e.move(0, 0) == b"GI100100"
    assert e.draw(767, 511) == b"GJ867611"
    assert e.pair(-100, -1) == b"000099"
    assert e.coords4() == b"IO"
    assert e.move(1535, 1023) == b"GI16351123"
    d = Decoder()
    cmds = d.feed(b"+-*/GI100100GJ867611IOGI16351123IP300400")
    pts = [c for c in cmds if isinstance(c, Point)]
    assert pts == [Point(0, 0), Point(767, 511), Point(1535, 1023), Point(200, 300)]


def test_pgplot_init_string_splits_into_its_seven_orders() -> None:
    cmds = Decoder().feed(b"\r\n+-*/DD000CBGAAAHE999CK1GH")
    assert [c for c in cmds if isinstance(c, Order)] == [
        Order("DD", (0,)), Order("CB"), Order("GA"), Order("AA"), Order("HE", (999,)),
        Order("CK", (1,)), Order("GH")]


def test_graphics_flag_only_at_line_start_until_gh() -> None:
    d = Decoder()
    cmds = d.feed(b"x+-*/DA")  # not at line start: all alpha text
    assert cmds == [AlphaText(b"x+-*/DA")]
    cmds = d.feed(b"\r+-*/GHBH" + b"abc+-*/DA")  # after GH: anywhere
    assert GraphicsFlag() in cmds and cmds[-1] == Order("DA")
    assert AlphaText(b"abc") in cmds


def test_gks_buffer_framing_cr_lf_is_harmless_in_graphics() -> None:
    d = Decoder()
    cmds = d.feed(b"\r+-*/DA\r\n\r+-*/GA\r\n\x00 \x7f\x11\x13GI")
    assert [c for c in cmds if isinstance(c, Order)] == [Order("DA"), Order("GA"), Order("GI")]
    # the second flag is taken in graphics mode, and the trailers are ignored silently
    assert cmds.count(GraphicsFlag()) == 2
    assert d.stats.unknown == d.stats.malformed == 0


def test_ags_encoder_omission_rules_byte_exact() -> None:
    enc = AgsPointEncoder()
    assert enc.encode(0, 0) == bytes((32, 96, 32, 64))  # first point: HiY LoY HiX LoX
    assert enc.encode(5, 0) == bytes((64 + 5,))  # only LoX changed
    assert enc.encode(5, 3) == bytes((96 + 3, 64 + 5))  # LoY changed
    assert enc.encode(40, 3) == bytes((96 + 3, 32 + 1, 64 + 8))  # HiX changed: LoY HiX LoX
    assert enc.encode(40, 40) == bytes((32 + 1, 96 + 8, 64 + 8))  # HiY and LoY
    assert enc.encode(40, 72) == bytes((32 + 2, 64 + 8))  # HiY only (LoY 8 again)
    hi = AgsPointEncoder(high_res=True)
    assert hi.encode(1100, 1030) == bytes((32, 96 + 4 + 1, 96 + 6, 32 + 2, 64 + 12))
    assert hi.encode(1101, 6) == bytes((96 + 1, 96 + 6, 64 + 13))  # EB changed: EB LoY
    with pytest.raises(ValueError):
        AgsPointEncoder().encode(1024, 0)


@pytest.mark.parametrize("high_res", [False, True])
def test_ags_decoder_inverts_encoder_split_anywhere(high_res: bool) -> None:
    rng = np.random.default_rng(7)
    top = 2048 if high_res else 1024
    pts = [tuple(int(v) for v in rng.integers(0, top, 2)) for _ in range(300)]
    pts += [(3, 3), (3, 3), (4, 3), (4, 35), (900, 35)]
    data = b"+-*/JH" + encode_points(pts, high_res) + b"\x1f"
    for step in (1, 2, 3, 7, len(data)):
        d = Decoder()
        cmds = [c for i in range(0, len(data), step) for c in d.feed(data[i:i + step])]
        got = np.concatenate([c.xy for c in cmds if isinstance(c, AgsPoints)])
        assert got.tolist() == [list(p) for p in pts]
        firsts = [c.move_first for c in cmds if isinstance(c, AgsPoints)]
        assert firsts[0] and not any(firsts[1:])
        assert cmds[-1] == AgsEnd()
        assert d.stats.malformed == 0 and d.stats.unknown == 0


def test_ags_escape_mask_and_dash_helpers() -> None:
    e = Encoder()
    data = e.abbreviated_dash12(0x924)
    assert data == b"JH\x1bM924\x1fFD"
    cmds = Decoder().feed(b"+-*/" + data)
    assert AgsEscape("M", b"924") in cmds and cmds[-1] == Order("FD")
    assert e.dash(0xF888) == b"DLF888FD"


def test_text_dots_block_ellipse_helpers() -> None:
    e = Encoder()
    assert e.text("AB C") == b"BAAB C\r"
    assert e.dots([0, 10, 15]) == b"DJ0AFZ"
    assert e.block(10, 20) == b"GJFHBG110120"
    assert e.ellipse(20, 1.0, solid=False) == b"JO356JM1200"  # CRYSTALS' circle: JO356
    assert e.ellipse(20, 1.0, solid=True) == b"JO356JN1200"
    cmds = Decoder().feed(b"+-*/" + e.text("Hi") + e.dots([1, 2]) + e.colour(3))
    assert GraphicsText(b"Hi") in cmds
    assert Dots(b"\x01\x02") in cmds and DotsEnd() in cmds
    assert cmds[-1] == Order("HI", (3,))


def test_dot_plotting_ends_at_z_across_feeds() -> None:
    d = Decoder()
    a = d.feed(b"+-*/DJ01")
    b = d.feed(b"2Z" + b"HI5")
    assert Dots(b"\x00\x01") in a
    assert b[0] == Dots(b"\x02") and b[1] == DotsEnd() and b[2] == Order("HI", (5,))


def test_cursor_report_format() -> None:
    assert format_report(ord("A"), 12, 345) == b"A012,345\r"
    assert format_report(ord("A"), 1535, 7, digits=4) == b"A1535,0007\r"
    r = parse_report(b"A012,345\r")
    assert (r.key, r.x, r.y) == (ord("A"), 12, 345)
    with pytest.raises(ValueError, match="byte 4"):
        parse_report(b"A012;345\r")


def test_unknown_and_malformed_are_counted_and_resynchronised() -> None:
    d = Decoder()
    cmds = d.feed(b"+-*/QQGAHIxHI5GI12a300400~DA")
    orders = [c for c in cmds if isinstance(c, Order)]
    assert Order("GA") in orders and Order("HI", (5,)) in orders and orders[-1] == Order("DA")
    assert Point(200, 300) in cmds
    assert d.stats.unknown >= 2  # QQ, Q?, ~
    assert d.stats.malformed == 2  # HIx and the pair broken by 'a'


def test_field_kinds_are_dec_or_hex() -> None:
    assert {f.kind for o in ORDERS for f in o.fields} <= {Kind.DEC, Kind.HEX}


def test_a_full_colour_opening_leaves_a_t5688_with_all_planes_and_the_given_lut() -> None:
    from camlab88.emulator.sigma import Terminal

    e = Encoder(high_res=True)
    lut = [(1, 2, 3), (250, 128, 7), (0, 255, 64)]
    term = Terminal("t5688")
    term.reg.write_mask = term.reg.display_mask = 0x0F  # a previous program's state
    term.reg.line_dashed = True
    term.feed(e.take_over() + e.full_colour_screen() + e.lut24_table(lut))
    assert (term.reg.write_mask, term.reg.display_mask) == (0xFF, 0xFF)
    assert not term.reg.line_dashed
    assert term.lut[:3].tolist() == [list(rgb) for rgb in lut]
