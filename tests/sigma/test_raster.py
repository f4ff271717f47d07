"""Firmware raster behaviour: the non-Bresenham line, fill with masks, double buffering."""

from __future__ import annotations

import math

import numpy as np

from camlab88.emulator.sigma.raster import boundary_fill, bresenham_points, firmware_line_points
from camlab88.protocols.sigma.abbreviated import encode_points
from tests.sigma.helpers import enc, graphics, lit

E = enc()


def test_firmware_line_differs_from_bresenham() -> None:
    """Thesis 6.4.1: the Sigma's steps disagree with Bresenham's."""
    fw = firmware_line_points(0, 0, 300, 7)
    br = bresenham_points(0, 0, 300, 7)
    assert (150, 3) in fw and (150, 4) in br  # the firmware steps one pixel later at x=150
    assert (193, 4) in fw and (193, 5) in br
    assert set(fw) != set(br)
    assert len(fw) == len(br) == 301  # both one pixel per column, both end points hit
    for p in ((0, 0), (300, 7)):
        assert p in fw and p in br
    # and it is what the terminal draws
    t = graphics(E.polyline([(0, 0), (300, 7)]))
    assert lit(t) == set(fw)


def test_firmware_line_hits_endpoints_of_long_lines() -> None:
    rng = np.random.default_rng(1)
    for _ in range(200):
        x0, y0, x1, y1 = (int(v) for v in rng.integers(0, 1536, 4))
        pts = firmware_line_points(x0, y0, x1, y1)
        assert (x0, y0) in pts and (x1, y1) in pts
        assert len(pts) == max(abs(x1 - x0), abs(y1 - y0)) + 1  # connected, one per step


def test_fill_stops_at_boundary_and_is_4_connected() -> None:
    # a diagonal wall is 8-connected only: a 4-connected fill must not leak through it
    t = graphics(E.colour(5) + E.polyline([(0, 100), (100, 0)]) + E.colour(2) + E.move(10, 10)
                 + E.fill(5))
    assert t.planes[10, 10] == 2 and t.planes[200, 200] == 0
    assert not (t.planes == 2)[np.add.outer(np.arange(512), np.arange(768)) > 100].any()


def test_fill_full_screen_and_seed_on_boundary() -> None:
    t = graphics(E.colour(3) + E.move(100, 100) + E.fill(9))
    assert (t.planes == 3).all()
    t = graphics(E.colour(3) + E.move(100, 100) + E.fill(0))  # seed is boundary colour
    assert not t.planes.any()


def test_fill_honours_write_and_read_masks() -> None:
    # planes 0-1 hold an outline in colour 1; planes 2-3 hold unrelated junk (colour 8)
    outline = E.polyline([(10, 10), (60, 10), (60, 60), (10, 60), (10, 10)])
    t = graphics(E.colour(8) + E.move(0, 0) + E.block(30, 30) + E.colour(1) + outline
                 + E.write_mask(0b0011) + E.display_mask(0b0011) + E.colour(2)
                 + E.move(40, 40) + E.fill(1))
    inside = t.planes[11:60, 11:60]
    assert ((inside & 3) == 2).all()  # filled in the write-enabled planes
    assert ((t.planes[11:31, 11:31] >> 2) == 2).all()  # junk in planes 2-3 untouched
    assert t.planes[5, 5] == 8 and t.planes[100, 100] == 0  # outside not filled
    # the read mask decides what counts as boundary: an outline drawn (write mask 0-1) over
    # junk in planes 2-3 reads 8|1 = 9; masked to planes 0-1 it is boundary colour 1 ...
    setup = (E.colour(8) + E.move(0, 0) + E.block(767, 511) + E.write_mask(0b0011)
             + E.colour(1) + outline + E.colour(2) + E.move(40, 40))
    t2 = graphics(setup + E.display_mask(0b0011) + E.fill(1))
    assert t2.planes[30, 30] == 8 | 2 and t2.planes[100, 100] == 8
    # ... unmasked it is not, and the fill runs over the whole screen
    t3 = graphics(setup + E.fill(1))
    assert t3.planes[30, 30] == 8 | 2 and t3.planes[100, 100] == 8 | 2


def test_fill_ends_when_fill_colour_is_invisible_through_the_write_mask() -> None:
    pix = np.zeros((512, 768), dtype=np.uint8)
    n = boundary_fill(pix, 5, 5, 0, 0, 15, 15)  # write mask 0: writes nothing
    assert n == 512 * 768 and not pix.any()


def test_double_buffer_trick_of_thesis_3_1_4() -> None:
    """Two 2-bit buffers in the 4 planes: draw hidden with the write mask, swap by the LUT."""
    show = [(0, 0, 0), (15, 15, 15), (15, 0, 0), (0, 0, 15)]

    def lut_showing(shift: int) -> bytes:
        return b"".join(E.lut(i, *show[(i >> shift) & 3]) for i in range(16))

    t = graphics(lut_showing(0))
    frames = []
    for k in range(4):
        shift = 2 if k % 2 == 0 else 0  # draw into the buffer that is not shown
        t.feed(E.write_mask(3 << shift) + E.erase() + E.colour(1 << shift)
               + E.polyline([(100 + 50 * k, 100), (100 + 50 * k, 300)]))
        before = t.frame().copy()
        t.feed(lut_showing(shift))
        frames.append((before, t.frame().copy()))
    for k, (before, after) in enumerate(frames):
        col = 100 + 50 * k
        # while drawing, the screen still showed the previous frame only
        assert not before[511 - 200, col].any()
        if k:
            assert before[511 - 200, col - 50].tolist() == [255, 255, 255]
        # after the swap: exactly the new frame
        assert after[511 - 200, col].tolist() == [255, 255, 255]
        assert not after[511 - 200, col - 50].any()


def test_abbreviated_and_standard_modes_draw_identical_pictures() -> None:
    rng = np.random.default_rng(3)
    chains = []
    for _ in range(20):
        n = int(rng.integers(2, 30))
        cx, cy = (int(v) for v in rng.integers(100, 400, 2))
        chains.append([(cx + int(90 * math.cos(i / 3)) + i, cy + int(80 * math.sin(i / 2)))
                       for i in range(n)])
    ngs = b"".join(E.colour(1 + k % 15) + E.dash(0xFE10 if k % 3 == 0 else 0xFFFF)
                   + E.polyline(c) for k, c in enumerate(chains))
    ags = b"".join(E.colour(1 + k % 15) + E.dash(0xFE10 if k % 3 == 0 else 0xFFFF)
                   + b"JH" + encode_points(c) + b"\x1f" for k, c in enumerate(chains))
    a, b = graphics(ngs), graphics(ags)
    assert np.array_equal(a.planes, b.planes) and a.planes.any()
    assert len(ags) < 0.75 * len(ngs)
