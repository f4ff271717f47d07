"""Convex polygons filled at pixel centres by one numba kernel (thesis §6.3.2's "fast"
drawing, on the host side).  Measured: with the view moving, the numpy version's per-face
arrays and its ~9,000 row slices a frame from Python were ~11 ms a frame at load 7, the
host's largest share; the kernel does a frame's 22 faces in well under a millisecond
(docs/perf/camera.md).  The arithmetic is the numpy version's, operation for operation, so
the pixels are the same.  One explicit signature (docs/development.md, numba's cache).
Imported where a face is first filled (raster.py), so a run that draws nothing never
imports numba."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from camlab88.base.kernel_notice import announce_compiles

announce_compiles("snooker visualiser", 1.0, __name__)


@njit("void(uint8[:, ::1], float64[:, ::1], uint8)", cache=True, nogil=True)
def _fill(img, xy, value):
    h, w = img.shape
    k = xy.shape[0]
    lo, hi = xy[0, 1], xy[0, 1]
    for i in range(k):
        lo, hi = min(lo, xy[i, 1]), max(hi, xy[i, 1])
    y0 = max(int(math.ceil(lo - 0.5)), 0)
    y1 = min(int(math.ceil(hi - 0.5)), h)  # rows y0 .. y1-1
    for y in range(y0, y1):
        cy = y + 0.5
        xl, xr = math.inf, -math.inf
        for i in range(k):
            ax, ay = xy[i, 0], xy[i, 1]
            bx, by = xy[(i + 1) % k, 0], xy[(i + 1) % k, 1]
            if (ay <= cy) != (by <= cy):
                x = ax + (cy - ay) * (bx - ax) / (by - ay)
                xl, xr = min(xl, x), max(xr, x)
        if xr < xl:
            continue
        il = int(min(max(math.ceil(xl - 0.5), 0.0), float(w)))
        ir = int(min(max(math.ceil(xr - 0.5), 0.0), float(w)))
        row = img[y]
        for x in range(il, ir):
            row[x] = value


def fill_convex(img: np.ndarray, xy: np.ndarray, value: int) -> None:
    """Fill the pixels of ``img`` (C-contiguous uint8) whose centres lie inside the convex
    polygon ``xy`` ((k, 2) screen pixels)."""
    _fill(img, np.ascontiguousarray(xy, dtype=np.float64), np.uint8(value))
