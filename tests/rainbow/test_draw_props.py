"""Drawing primitives against brute-force definitions, and clipping that changes nothing."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from emulator.rainbow import Rainbow
from emulator.rainbow.memory import VideoMemory

far = st.integers(-3000, 3000)
near = st.integers(-20, 80)


def _pads():
    r = Rainbow(memory=VideoMemory(256, 256))
    big = r.create_pad(200, 200, 1)
    small = r.create_pad(60, 50, 1, plane=1)  # a window onto big's (70..130, 80..130)
    return r, r.canvas(big), r.canvas(small)


@settings(max_examples=60, deadline=None)
@given(near | far, near | far, near | far, near | far)
def test_line_clipping_is_invisible(x0, y0, x1, y1) -> None:
    """A line drawn into a small pad equals the same window of the line in a large pad."""
    r, big, small = _pads()
    big.line(x0 + 70, y0 + 80, x1 + 70, y1 + 80, 1)
    small.line(x0, y0, x1, y1, 1)
    want = big.read()[80:130, 70:130]
    if max(abs(v) for v in (x0, y0, x1, y1)) < 60:  # fully inside big: compare exactly
        assert np.array_equal(small.read(), want)
    # and the line always contains its end points when they are in the pad
    for x, y in ((x0, y0), (x1, y1)):
        if 0 <= x < 60 and 0 <= y < 50:
            assert small.read()[y, x] == 1


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(near, near), min_size=3, max_size=8))
def test_polygon_matches_crossing_rule(points) -> None:
    _, _, c = _pads()
    c.polygon(points, 1)
    p = np.array(points, float)
    q = np.roll(p, -1, axis=0)
    yy, xx = np.mgrid[0:50, 0:60] + 0.5
    inside = np.zeros((50, 60), bool)
    for (ax, ay), (bx, by) in zip(p, q):
        if ay == by:
            continue
        crosses = (ay > yy) != (by > yy)
        inside ^= crosses & (xx < ax + (yy - ay) * (bx - ax) / (by - ay))
    assert np.array_equal(c.read() == 1, inside)


@settings(max_examples=40, deadline=None)
@given(near | far, near | far, st.integers(0, 100) | st.integers(0, 2**31 - 1))
def test_circle_is_the_disc_of_centres(cx, cy, r) -> None:
    _, _, c = _pads()
    c.circle(cx, cy, r, 1)
    yy, xx = np.mgrid[0:50, 0:60]
    dy = yy - cy
    half = np.floor(np.sqrt(np.maximum(r * r - dy * dy, 0).astype(float)))
    want = (np.abs(dy) <= r) & (np.abs(xx - cx) <= half)
    assert np.array_equal(c.read() == 1, want)
