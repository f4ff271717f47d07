"""numba kernels for seed finding: 4-connected components of the pixels a boundary leaves
free (the way the firmware's flood filler spreads), and each component's deepest pixel.

Measured to pay: a pure-Python scan of a 768x512 painting area takes ~0.4 s, these take
about a millisecond.  Each kernel has one explicit signature (docs/development.md).
Imported where seeds are first found (seeds.py), so a command that paints nothing never
imports numba.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from camlab88.base.kernel_notice import announce_compiles

# one line on stderr if the cache is cold: measured 8 s at load 7 on the 2-core machine
announce_compiles("KAS painting", 4.0, __name__)

_SIG_LABEL = "int64(uint8[:, ::1], int32[:, ::1], int32[::1])"
_SIG_DEEP = "void(uint8[:, ::1], int32[:, ::1], int32[:, ::1], int64[::1], int32[::1])"


@njit(_SIG_LABEL, cache=True, nogil=True)
def _label(wall, labels, stack):
    """labels: 0 on the wall, 1..n for the free components (scan-line fill). Returns n."""
    h, w = wall.shape
    for y in range(h):
        for x in range(w):
            labels[y, x] = 0 if wall[y, x] else -1
    n = 0
    for y0 in range(h):
        for x0 in range(w):
            if labels[y0, x0] != -1:
                continue
            n += 1
            stack[0] = y0 * w + x0
            top = 1
            while top > 0:
                top -= 1
                y = stack[top] // w
                x = stack[top] - y * w
                if labels[y, x] != -1:
                    continue
                xl = x
                while xl > 0 and labels[y, xl - 1] == -1:
                    xl -= 1
                xr = x
                while xr < w - 1 and labels[y, xr + 1] == -1:
                    xr += 1
                for xi in range(xl, xr + 1):
                    labels[y, xi] = n
                for ny in (y - 1, y + 1):
                    if 0 <= ny < h:
                        inrun = False
                        for xi in range(xl, xr + 1):
                            if labels[ny, xi] != -1:
                                inrun = False
                            elif not inrun:
                                stack[top] = ny * w + xi
                                top += 1
                                inrun = True
    return n


@njit(_SIG_DEEP, cache=True, nogil=True)
def _deepest(wall, labels, dist, best, depth):
    """3-4 chamfer distance to the wall; best[k] = y*w+x of component k's deepest pixel
    (first in scan order on ties), depth[k] its distance (3 = one pixel)."""
    h, w = wall.shape
    big = 1 << 28
    for y in range(h):
        for x in range(w):
            dist[y, x] = 0 if wall[y, x] else big
    for y in range(h):
        for x in range(w):
            d = dist[y, x]
            if d == 0:
                continue
            if x > 0:
                d = min(d, dist[y, x - 1] + 3)
            if y > 0:
                d = min(d, dist[y - 1, x] + 3)
                if x > 0:
                    d = min(d, dist[y - 1, x - 1] + 4)
                if x < w - 1:
                    d = min(d, dist[y - 1, x + 1] + 4)
            dist[y, x] = d
    for y in range(h - 1, -1, -1):
        for x in range(w - 1, -1, -1):
            d = dist[y, x]
            if d == 0:
                continue
            if x < w - 1:
                d = min(d, dist[y, x + 1] + 3)
            if y < h - 1:
                d = min(d, dist[y + 1, x] + 3)
                if x < w - 1:
                    d = min(d, dist[y + 1, x + 1] + 4)
                if x > 0:
                    d = min(d, dist[y + 1, x - 1] + 4)
            dist[y, x] = d
    for k in range(depth.shape[0]):
        depth[k] = -1
    for y in range(h):
        for x in range(w):
            k = labels[y, x]
            if k > 0 and dist[y, x] > depth[k]:
                depth[k] = dist[y, x]
                best[k] = y * w + x


def components(wall: np.ndarray) -> tuple[np.ndarray, int, np.ndarray, np.ndarray]:
    """(labels, n, best, depth) for a uint8 wall map: see _label and _deepest."""
    wall = np.ascontiguousarray(wall, dtype=np.uint8)
    h, w = wall.shape
    labels = np.empty((h, w), dtype=np.int32)
    stack = np.empty(2 * h * w + 16, dtype=np.int32)
    n = int(_label(wall, labels, stack))
    dist = np.empty((h, w), dtype=np.int32)
    best = np.zeros(n + 1, dtype=np.int64)
    depth = np.empty(n + 1, dtype=np.int32)
    _deepest(wall, labels, dist, best, depth)
    return labels, n, best, depth
