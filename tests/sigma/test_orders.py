"""One behaviour test per order of the table (the meta-test checks none is missing)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pytest

from camlab88.emulator.sigma import Terminal
from camlab88.protocols.sigma import ORDERS
from tests.sigma.helpers import FLAG, enc, graphics, lit, run

E = enc()
BEHAVIOUR: dict[str, Callable[[], None]] = {}


def covers(*codes: str) -> Callable[[Callable[[], None]], Callable[[], None]]:
    def deco(fn: Callable[[], None]) -> Callable[[], None]:
        for c in codes:
            BEHAVIOUR[c] = fn
        return fn
    return deco


@covers("BH")
def test_bh_returns_to_alpha() -> None:
    t = graphics(E.alpha_mode() + b"HI")
    assert t.alpha.chars[0, :2].tobytes() == b"HI"


@covers("HH")
def test_hh_resets_everything() -> None:
    t = graphics(E.colour(3) + E.lut(0, 15, 0, 0) + E.polyline([(0, 0), (50, 50)]) + E.reset()
                 + E.move(1, 1))
    assert not t.planes.any() and t.reg.colour == 1 and t.lut[0].tolist() == [0, 0, 0]
    assert (t.reg.pen_x, t.reg.pen_y) == (1, 1)  # still in graphics mode after the NULs


@covers("DD", "DG", "DF", "HE")
def test_setting_registers() -> None:
    t = graphics(b"DD000DG017DF019HE999")
    assert (t.reg.sequence_length, t.reg.xon_char, t.reg.xoff_char, t.reg.prompt_char) == \
        (0, 17, 19, 999)
    assert t.stats["unknown"] == t.stats["malformed"] == 0
    # the values are stored, not merely the power-on ones left alone
    t = graphics(b"DD123DG018DF020HE500")
    assert (t.reg.sequence_length, t.reg.xon_char, t.reg.xoff_char, t.reg.prompt_char) == \
        (123, 18, 20, 500)


@covers("GA")
def test_ga_graphics_display_on() -> None:
    t = graphics(E.polyline([(0, 0), (700, 0)]))
    t.reg.graphics_on = False
    assert not t.frame().any()
    t.feed(E.graphics_on())
    assert t.frame()[511, 100].tolist() == [255, 255, 255]


@covers("AA", "AJ")
def test_alpha_display_on_off() -> None:
    t = run(b"TEXT\r\n" + FLAG + E.alpha_off())
    assert not t.frame().any()
    t.feed(E.alpha_on())
    assert t.frame().any()


@covers("CK", "CA", "CB")
def test_cursor_shapes_and_visibility() -> None:
    t = graphics(E.move(100, 100) + E.cursor_attach() + E.cursor_shape(1) + E.cursor_on())
    f = t.frame()
    assert f[511 - 100, :].all() and f[:, 100].all()  # full-screen crosshair
    t.feed(E.cursor_shape(0))
    f = t.frame()
    assert f[511 - 100, 95:106].all() and not f[511 - 100, 300].any()  # small cross
    t.feed(E.cursor_off())
    assert not t.frame().any()


@covers("GH")
def test_gh_flag_anywhere() -> None:
    t = graphics(E.flag_anywhere() + E.alpha_mode() + b"ab" + FLAG + E.move(5, 5))
    assert (t.reg.pen_x, t.reg.pen_y) == (5, 5)
    t2 = graphics(E.alpha_mode() + b"ab" + FLAG + E.move(5, 5))
    assert (t2.reg.pen_x, t2.reg.pen_y) == (0, 0)


@covers("IE", "CF", "GM")
def test_cursor_device_selection() -> None:
    t = graphics(E.cursor_device(3))
    assert t.reg.cursor_tablet
    t.tablet(10, 20, False)
    assert (t.reg.cursor_x, t.reg.cursor_y) == (10, 20)
    t.cursor_keys(5, 5)  # keys do not move a tablet cursor
    assert (t.reg.cursor_x, t.reg.cursor_y) == (10, 20)
    t.feed(E.cursor_joystick())
    t.cursor_keys(5, -5)
    assert (t.reg.cursor_x, t.reg.cursor_y) == (15, 15)
    t.feed(E.cursor_device(3) + E.normal_mode())
    assert not t.reg.cursor_tablet


@covers("IO", "IP")
def test_io_ip_coordinate_width() -> None:
    t = graphics(E.coords4() + b"GI01000100GJ06000100" + E.coords3() + b"GI100200GJ150200")
    assert {(x, 0) for x in range(0, 501)} <= lit(t)
    assert {(x, 100) for x in range(0, 51)} <= lit(t)


@covers("DA")
def test_da_erases_through_the_write_mask() -> None:
    t = graphics(E.colour(15) + E.block(20, 20) + E.write_mask(0b0011) + E.erase())
    assert t.planes[0:21, 0:21].min() == 12 and t.planes[0:21, 0:21].max() == 12


@covers("GI", "GJ")
def test_pen_up_moves_pen_down_draws_polyline() -> None:
    t = graphics(b"GI110110GJ120110120120GI200200300300")
    assert {(x, 10) for x in range(10, 21)} | {(20, y) for y in range(10, 21)} == lit(t)
    assert (t.reg.pen_x, t.reg.pen_y) == (200, 200)


@covers("FA", "FB")
def test_pgplot_colours() -> None:
    t = graphics(E.pen_draw() + E.polyline([(0, 0), (10, 0)]) + E.pen_erase()
                 + E.polyline([(0, 0), (4, 0)]))
    assert lit(t) == {(x, 0) for x in range(5, 11)}
    t = graphics(E.colour(5) + E.pen_draw() + E.polyline([(0, 0), (3, 0)]))
    assert t.planes[0, :4].tolist() == [1, 1, 1, 1]  # FA draws in colour 1, not the last HI


@covers("DL", "FD", "FC", "FG")
def test_dash_mask_modes_and_phase() -> None:
    t = graphics(E.dash(0xF0F0) + E.polyline([(0, 0), (15, 0)]))
    assert lit(t) == {(x, 0) for x in (0, 1, 2, 3, 8, 9, 10, 11)}
    # phase continues across vectors: 0..5 then 6..15 as one pattern
    t = graphics(E.dash(0xF0F0) + E.polyline([(0, 0), (5, 0), (15, 0)]))
    assert lit(t) == {(x, 0) for x in (0, 1, 2, 3, 8, 9, 10, 11)}
    # a separate vector also continues the phase; FG restarts it
    t = graphics(E.dash(0xF0F0) + E.polyline([(0, 0), (5, 0)]) + E.polyline([(0, 1), (3, 1)]))
    assert {(x, 1) for x in range(4)} & lit(t) == {(2, 1), (3, 1)}
    t = graphics(E.dash(0xF0F0) + E.polyline([(0, 0), (2, 0), (5, 0)])
                 + E.polyline([(0, 1), (3, 1)]))
    assert {(x, 1) for x in range(4)} & lit(t) == {(2, 1), (3, 1)}
    t = graphics(E.dash(0xF0F0) + E.polyline([(0, 0), (5, 0)]) + E.line_reset()
                 + E.polyline([(0, 1), (3, 1)]))
    assert {(x, 1) for x in range(4)} <= lit(t)
    t = graphics(E.dash(0xF0F0) + E.line_solid() + E.polyline([(0, 0), (15, 0)]))
    assert lit(t) == {(x, 0) for x in range(16)}


@covers("EK")
def test_ek_twelve_bit_mask() -> None:
    t = graphics(E.dash_mask12(0x924) + E.line_dashed() + E.polyline([(0, 0), (11, 0)]))
    assert lit(t) == {(0, 0), (3, 0), (6, 0), (9, 0)}


def test_ags_escape_m_and_r_set_twelve_bit_dash_patterns() -> None:
    """RAL GKS's A-series dashes: ESC M hhh sets a 12-bit mask, ESC R + 3 spaces the built-in
    3 on 3 off pattern; both repeat every 12 steps."""
    t = graphics(E.abbreviated_dash12(0x924) + E.polyline([(0, 0), (23, 0)]))
    assert lit(t) == {(x, 0) for x in (0, 3, 6, 9, 12, 15, 18, 21)}
    t = graphics(b"JH\x1bR   \x1f" + E.line_dashed() + E.polyline([(0, 0), (23, 0)]))
    assert lit(t) == {(x, 0) for x in (0, 1, 2, 6, 7, 8, 12, 13, 14, 18, 19, 20)}
    assert t.stats["unknown"] == t.stats["malformed"] == 0


@covers("HI", "KI")
def test_colour_indices() -> None:
    t = graphics(E.colour(9) + E.polyline([(0, 0), (3, 0)]))
    assert t.planes[0, 0] == 9
    t8 = graphics(E.colour(200) + E.polyline([(0, 0), (3, 0)]), model="t5688")
    assert t8.planes[0, 0] == 200
    t4 = graphics(E.colour8(0xC5) + E.polyline([(0, 0), (3, 0)]))
    assert t4.planes[0, 0] == 5  # a 4-plane terminal keeps the low 4 bits


@covers("BA")
def test_ba_graphics_text() -> None:
    t = graphics(E.colour(2) + E.move(100, 100) + E.text("I"))
    pts = lit(t)
    assert len(pts) == 11  # our 'I': top bar 3 + stem 5 + bottom bar 3
    assert min(x for x, _ in pts) >= 101 and min(y for _, y in pts) >= 101
    assert (t.reg.pen_x, t.reg.pen_y) == (108, 100)


def test_ba_text_ends_at_cr_and_keeps_256_characters() -> None:
    t = graphics(b"BA" + b"I" * 300 + b"\r" + E.colour(3))
    assert t.reg.pen_x == 256 * 8  # 256 cells drawn, the rest dropped and counted
    assert t.stats["malformed"] == 1
    assert t.reg.colour == 3  # CR ended the text: HI3 is an order again


@covers("FH", "BG")
def test_solid_and_outline_blocks() -> None:
    t = graphics(E.move(10, 10) + E.block(20, 15))
    assert lit(t) == {(x, y) for x in range(10, 21) for y in range(10, 16)}
    t = graphics(E.move(10, 10) + E.block(20, 15, solid=False) + E.move(0, 0) + b"GJ101101")
    pts = lit(t)
    assert (15, 12) not in pts and (10, 12) in pts and (20, 15) in pts
    assert {(0, 0), (1, 1)} <= pts  # BG was one-shot: the next pair draws a line


@covers("DJ")
def test_dj_dot_plotting() -> None:
    t = graphics(E.move(5, 7) + E.dots([1, 0, 15, 3]) + E.dots([2]))
    assert t.planes[7, 5:10].tolist() == [1, 0, 15, 3, 2]  # DJ again carries on (GKS flush)
    assert (t.reg.pen_x, t.reg.pen_y) == (10, 7)
    t = graphics(E.move(5, 7) + b"DJ10F" + b"\r\n" + b"3Z")
    assert t.planes[7, 5:9].tolist() == [1, 0, 15, 3]  # CR LF inside a run are ignored


@pytest.mark.parametrize("split", range(1, 9))
def test_dj_without_z_ends_at_an_order(split: int) -> None:
    """A dot A-F and a following non-hex letter that form an order end DJ: DJ12BH is two dots
    and BH, wherever the feed is split; two hex letters (FA, CA...) are always dots."""
    data = E.move(5, 7) + b"DJ12BH"
    t = Terminal("t5684")
    t.feed(FLAG + data[:split])
    t.feed(data[split:])
    assert t.planes[7, 5:8].tolist() == [1, 2, 0]
    assert t.decoder.mode.value == "alpha" and t.stats["unknown"] == 0
    t = graphics(E.move(5, 7) + b"DJ3FAEK924GJ" + E.pair(20, 7))
    assert t.planes[7, 5:8].tolist() == [3, 15, 10]  # FA dots; E+K is the order EK
    assert t.reg.dash_mask == 0x924 and t.reg.dash_bits == 12
    assert t.planes[7, 8:21].tolist() == [1] * 13  # and GJ draws on from the pen at x = 8
    t = graphics(E.move(5, 7) + b"DJ1C2Z")
    assert t.planes[7, 5:8].tolist() == [1, 12, 2]  # C followed by a digit is a dot


@covers("JK", "KK")
def test_fill_orders() -> None:
    square = E.polyline([(10, 10), (30, 10), (30, 30), (10, 30), (10, 10)])
    t = graphics(E.colour(3) + square + E.colour(6) + E.move(20, 20) + E.fill(3))
    assert (t.planes[11:30, 11:30] == 6).all() and t.planes[5, 5] == 0
    t8 = graphics(E.colour(0x93) + square + E.colour(7) + E.move(20, 20) + E.fill8(0x93),
                  model="t5688")
    assert (t8.planes[11:30, 11:30] == 7).all()


@covers("JO", "JM", "JN")
def test_ellipses() -> None:
    t = graphics(E.move(100, 100) + E.ellipse(20, 2.0, solid=True))
    pts = lit(t)
    xs = [x for x, _ in pts]
    ys = [y for _, y in pts]
    assert (min(xs), max(xs), min(ys), max(ys)) == (80, 120, 90, 110)
    t = graphics(E.move(100, 100) + E.ellipse(20, 1.0))
    pts = lit(t)
    assert (100, 100) not in pts and (120, 100) in pts and (100, 80) in pts
    t = graphics(E.move(100, 100) + b"JM0500")  # radius 50 - 100 < 0: impossible, skipped
    assert not t.planes.any() and t.stats["errors"] == 1


@covers("JH")
def test_jh_abbreviated_polyline_first_point_moves() -> None:
    t = graphics(E.abbreviated_polyline([(5, 5), (9, 5), (9, 9)]))
    assert lit(t) == {(x, 5) for x in range(5, 10)} | {(9, y) for y in range(5, 10)}


@covers("JG", "KG")
def test_lut_entries_take_effect_at_once() -> None:
    t = graphics(E.colour(4) + E.block(767, 511))
    assert t.frame()[0, 0].tolist() == [0, 0, 255]
    t.feed(E.lut(4, 15, 8, 1))
    assert t.frame()[0, 0].tolist() == [255, 136, 17]
    t.feed(E.lut24(4, 0x12, 0x34, 0xFF))
    assert t.frame()[0, 0].tolist() == [17, 51, 255]  # 4 bits per gun kept on a T5684
    t8 = graphics(E.colour(77) + E.block(767, 511) + E.lut24(77, 0x12, 0x34, 0x56),
                  model="t5688")
    assert t8.frame()[5, 5].tolist() == [0x12, 0x34, 0x56]
    t8 = graphics(E.colour(7) + E.block(767, 511) + E.lut(7, 15, 8, 1), model="t5688")
    assert t8.frame()[5, 5].tolist() == [255, 136, 17]  # 4-bit guns on a 24-bit LUT: 15 is full


@covers("CE", "HF")
def test_cursor_report_after_hf() -> None:
    t = graphics(E.move(123, 45) + E.cursor_attach() + E.cursor_joystick() + E.cursor_on()
                 + E.cursor_report())
    sent: list[bytes] = []
    t.on_output = sent.append
    t.cursor_keys(-3, 2)
    t.key("A")
    assert sent == [b"A120,047\r"]
    t.key("x")  # no report armed: typed keys go up the line
    assert sent[-1] == b"x"
    t.feed(E.move(300, 200) + E.polyline([(300, 200), (310, 220)]))
    assert (t.reg.cursor_x, t.reg.cursor_y) == (310, 220)  # the attached cursor follows the pen


@covers("KW")
def test_write_mask_protects_planes() -> None:
    t = graphics(E.colour(15) + E.block(9, 9) + E.write_mask(0b0100) + E.colour(0)
                 + E.move(0, 0) + E.block(9, 9))
    assert (t.planes[0:10, 0:10] == 0b1011).all()


@covers("KD")
def test_display_mask_selects_planes_seen() -> None:
    t = graphics(E.colour(0b0110) + E.block(9, 9) + E.display_mask(0b0100))
    assert t.indices()[0, 0] == 0b0100
    assert t.frame()[511, 0].tolist() == t.lut[4].tolist()


@covers("KQ")
def test_t5688_quadrants_and_half_size() -> None:
    e8 = enc("t5688")
    t = graphics(e8.coords4() + e8.colour(2) + e8.move(800, 600) + e8.block(1535, 1023),
                 model="t5688")
    assert not t.frame().any()  # quadrant 0 (bottom left) shows nothing
    t.feed(e8.view(3))
    assert (t.frame()[:512 - 88, 32:] == t.lut[2]).all()
    t.feed(e8.view(4))
    f = t.frame()
    assert f[0, 767].tolist() == t.lut[2].tolist() and not f[511, 0].any()
    assert f[511 - 300, 400].tolist() == t.lut[2].tolist()  # (800, 600) / 2
    t4 = graphics(b"KQ3")
    assert t4.stats["errors"] == 1  # a T5684 has no quadrants
    # a block in the bottom right quarter only: quadrant 1 shows it, quadrant 2 does not
    t = graphics(e8.coords4() + e8.colour(2) + e8.move(768, 0) + e8.block(1535, 511),
                 model="t5688")
    t.feed(e8.view(1))
    assert (t.frame() == t.lut[2]).all()
    t.feed(e8.view(2))
    assert not t.frame().any()


def test_t5688_half_size_keeps_one_pixel_lines() -> None:
    """Each screen pixel of KQ4 shows the highest index of its 2x2 block: thin lines on odd
    rows and columns stay visible, and no colour is invented."""
    e8 = enc("t5688")
    lines = e8.coords4() + e8.colour(3)
    for k in range(8):  # horizontal and vertical 1-pixel lines on even and odd rows/columns
        lines += e8.polyline([(100, 201 + k), (1400, 201 + k)]) if k % 2 else b""
        lines += e8.polyline([(301 + k, 50), (301 + k, 950)]) if k % 2 == 0 else b""
    t = graphics(lines + e8.colour(5) + e8.polyline([(11, 11), (11, 11)]) + e8.view(4),
                 model="t5688")
    idx = t.indices()
    for k in range(8):
        if k % 2:
            assert (idx[(201 + k) // 2, 50:700] == 3).all(), f"row {201 + k} vanished"
        else:
            assert (idx[25:475, (301 + k) // 2] == 3).all(), f"column {301 + k} vanished"
    assert idx[5, 5] == 5  # a single odd pixel survives
    assert set(np.unique(idx).tolist()) <= {0, 3, 5}


def test_every_order_has_a_behaviour_test() -> None:
    missing = [o.code for o in ORDERS if o.code not in BEHAVIOUR]
    assert not missing, f"orders without a behaviour test: {missing}"


def test_out_of_range_coordinates_clip() -> None:
    t = graphics(E.polyline([(-100, -100), (899, 899)]))
    assert t.planes[0, 0] == 1 and t.planes[511, 511] == 1
    assert np.count_nonzero(t.planes) == 512
