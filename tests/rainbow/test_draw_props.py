"""Drawing primitives against brute-force definitions, and clipping that changes nothing."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.emulator.rainbow import Rainbow
from camlab88.emulator.rainbow.memory import VideoMemory

far = st.integers(-3000, 3000)
near = st.integers(-20, 80)


def _pads():
    r = Rainbow(memory=VideoMemory(256, 256))
    big = r.create_pad(200, 200, 1)
    small = r.create_pad(60, 50, 1, plane=1)  # a window onto big's (70..130, 80..130)
    return r, r.canvas(big), r.canvas(small)


def _line_pixels(x0: int, y0: int, x1: int, y1: int) -> set[tuple[int, int]]:
    """Every pixel of the whole, unclipped line, from the definition: for t = 0..n (n the
    major-axis length) the point x0 + dx*t/n, y0 + dy*t/n with each coordinate rounded to
    nearest, halves up (exact integer arithmetic, no clipping anywhere)."""
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy))
    if n == 0:
        return {(x0, y0)}
    t = np.arange(n + 1, dtype=np.int64)

    def rounded(d: int) -> np.ndarray:
        q, r = np.divmod(d * t, n)  # d*t/n = q + r/n with 0 <= r < n
        return q + (2 * r >= n)

    return set(zip((x0 + rounded(dx)).tolist(), (y0 + rounded(dy)).tolist()))


@settings(max_examples=60, deadline=None)
@given(near | far, near | far, near | far, near | far)
def test_line_clipping_is_invisible(x0, y0, x1, y1) -> None:
    """A line drawn into a small pad shows exactly the pixels of the whole line that fall in
    the pad, however far away its ends are; and the same window of a larger pad agrees."""
    r, big, small = _pads()
    small.line(x0, y0, x1, y1, 1)
    want = np.zeros((50, 60), bool)
    for x, y in _line_pixels(x0, y0, x1, y1):
        if 0 <= x < 60 and 0 <= y < 50:
            want[y, x] = True
    got = small.read() == 1
    diff = np.argwhere(got != want)
    assert len(diff) == 0, f"{len(diff)} pixels differ, first at (y, x) {diff[0]}"
    big.line(x0 + 70, y0 + 80, x1 + 70, y1 + 80, 1)
    assert np.array_equal(big.read()[80:130, 70:130] == 1, want)


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
