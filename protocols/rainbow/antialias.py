"""Anti-aliased polygon coverage, computed on the program side (as Appendix I's red polygon
was): the fraction of each pixel inside the polygon, quantised to ``levels`` shades."""

from __future__ import annotations

import numpy as np


def coverage(points: list[tuple[float, float]], width: int, height: int, levels: int = 32,
             samples: int = 4) -> np.ndarray:
    """(height, width) array of 0..levels-1: 0 outside, levels-1 fully inside."""
    p = np.asarray(points, dtype=np.float64)
    off = (np.arange(samples) + 0.5) / samples
    xs = (np.arange(width)[:, None] + off[None, :]).ravel()
    ys = (np.arange(height)[:, None] + off[None, :]).ravel()[:, None]
    inside = np.zeros((ys.size, xs.size), bool)
    for (x0, y0), (x1, y1) in zip(p, np.roll(p, -1, axis=0)):
        if y0 == y1:
            continue
        crosses = (y0 > ys) != (y1 > ys)
        inside ^= crosses & (xs < x0 + (ys - y0) * (x1 - x0) / (y1 - y0))
    frac = inside.reshape(height, samples, width, samples).mean(axis=(1, 3))
    return np.rint(frac * (levels - 1)).astype(np.uint8)
