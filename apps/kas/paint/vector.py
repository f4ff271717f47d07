"""The host's copy of the terminal's vector algorithm, so it knows every pixel a boundary
will set before sending it (thesis §3.3: seed points "guaranteed to be within the area").

The T5688's lines are a 12-bit fixed-point DDA (the reconstruction in docs/fidelity/
sigma.md: the major axis steps a pixel at a time, the minor axis adds the slope truncated to
1/4096 to an accumulator starting at one half).  A line's pixels depend on its direction,
so a boundary must be sent in the order it was rasterised here.  tests/kas_paint checks
this copy pixel for pixel against the emulated terminal.
"""

from __future__ import annotations

import numpy as np

FRACTION_BITS = 12
HALF = 1 << (FRACTION_BITS - 1)


def polyline_pixels(pts: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Pixels (x, y) set by drawing the polyline ``pts`` (n, 2) ints, with the index of the
    segment that set each (a lone point sets itself)."""
    p = np.asarray(pts, dtype=np.int64).reshape(-1, 2)
    if len(p) == 1:
        return p[:, 0].copy(), p[:, 1].copy(), np.zeros(1, dtype=np.int64)
    x0, y0 = p[:-1, 0], p[:-1, 1]
    dx, dy = p[1:, 0] - x0, p[1:, 1] - y0
    sx, sy = np.where(dx >= 0, 1, -1), np.where(dy >= 0, 1, -1)
    adx, ady = dx * sx, dy * sy
    xmajor = adx >= ady
    n = np.where(xmajor, adx, ady)
    slope = np.where(xmajor, (ady << FRACTION_BITS) // np.maximum(adx, 1),
                     (adx << FRACTION_BITS) // np.maximum(ady, 1))
    counts = n + 1
    seg = np.repeat(np.arange(len(n)), counts)
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    i = np.arange(int(counts.sum())) - np.repeat(starts, counts)
    minor = (HALF + i * slope[seg]) >> FRACTION_BITS
    xm = xmajor[seg]
    x = x0[seg] + sx[seg] * np.where(xm, i, minor)
    y = y0[seg] + sy[seg] * np.where(xm, minor, i)
    return x, y, seg


def stamp(wall: np.ndarray, pts: np.ndarray) -> None:
    """Set the polyline's pixels in ``wall`` (uint8 [y, x]), clipped like the terminal."""
    x, y, _ = polyline_pixels(pts)
    h, w = wall.shape
    ok = (x >= 0) & (x < w) & (y >= 0) & (y < h)
    wall[y[ok], x[ok]] = 1
