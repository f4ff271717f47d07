"""Regions (beyond the thesis, §3.3 last paragraph): any face of the drawing's lines, found
again in every frame though it is bounded by different parts of the chains, and small gaps
closed by a tolerance instead of the colour leaking."""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from camlab88.apps.kas.paint import areas
from camlab88.apps.kas.paint.ops import Op, OpsFile
from tests.kas_paint.oracle import seg_distance
from tests.kas_paint.test_autopaint import _paint

R = 2.0


def _circle(n: int = 48) -> np.ndarray:
    t = np.linspace(0, 2 * np.pi, n + 1)
    return np.column_stack([R * np.cos(t), R * np.sin(t)])


def _pixel_field() -> tuple[np.ndarray, np.ndarray]:
    ys, xs = np.mgrid[0:areas.AREA_H, 0:areas.AREA_W]
    return (xs - areas.AREA_W / 2) / areas.SCALE, (ys - areas.AREA_H / 2) / areas.SCALE


def test_region_cut_by_a_moving_line_is_followed() -> None:
    """A circle cut by a line that rises through it: the part above the line is bounded by
    a different arc of the circle and stretch of the line in every frame."""
    heights = np.linspace(-1.2, 1.2, 9)
    frames = [Drawing([Chain.from_points(_circle()),
                       Chain.from_points([(-3.0, h), (3.0, h)], 2)]) for h in heights]
    seq = AnimSequence(frames)
    ops = OpsFile(ops=[Op("region", 6, at=(0.0, (heights[4] + R) / 2), line_no=9)], painted=5)
    got, rep = _paint(seq, ops)
    assert rep.failures == []
    fx, fy = _pixel_field()
    px_per_in = areas.SCALE
    for h, planes in zip(heights, got, strict=True):
        painted = (planes & 0x1F) == 6
        r = np.hypot(fx, fy)
        # margins of 2 px from both lines
        want = (fy > h + 2 / px_per_in) & (r < R - 2 / px_per_in)
        away = (fy < h - 2 / px_per_in) | (r > R + 2 / px_per_in)
        assert not np.any(want & ~painted), f"missed pixels at h={h}"
        assert not np.any(away & painted), f"leak at h={h}"


def _square_with_gap(gap: float) -> Chain:
    return Chain.from_points([(-1.0 + gap, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0),
                              (-1.0, -1.0)])


def test_gap_tolerance_closes_a_near_miss() -> None:
    seq = AnimSequence([Drawing([_square_with_gap(0.06)])])  # a 3.5-pixel gap
    leaky = OpsFile(ops=[Op("region", 4, at=(0.0, 0.0), line_no=8)], painted=1)
    _, rep = _paint(seq, leaky)
    assert [(f.frame, f.line) for f in rep.failures] == [(1, 8)]
    closed = OpsFile(ops=[Op("region", 4, at=(0.0, 0.0), line_no=8)], gap=0.1, painted=1)
    got, rep = _paint(seq, closed)
    assert rep.failures == []
    painted = (got[0] & 0x1F) == 4
    ys, xs = np.nonzero(painted)
    fx, fy = (xs - areas.AREA_W / 2) / areas.SCALE, (ys - areas.AREA_H / 2) / areas.SCALE
    assert np.all((np.abs(fx) <= 1.0 + 1.5 / areas.SCALE) & (np.abs(fy) <= 1.0 + 1.5 / areas.SCALE))
    assert painted.sum() > 0.9 * (2 * areas.SCALE) ** 2


def test_gap_segment_is_where_the_near_miss_is() -> None:
    from camlab88.apps.kas.paint import shape

    d = Drawing([_square_with_gap(0.06)])
    (seg,) = shape.gap_segments(d, 0.1)
    assert np.allclose(sorted(map(tuple, seg)), [(-1.0, -1.0), (-0.94, -1.0)])
    assert shape.gap_segments(d, 0.05) == []
    assert float(seg_distance([seg], np.array([-0.97]), np.array([-1.0]))[0]) == 0.0
