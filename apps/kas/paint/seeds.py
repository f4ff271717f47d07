"""Seed points guaranteed inside (thesis §3.3): "the necessity of determining a seed point
which is guaranteed to be within the area to be filled.  It may even be necessary to find a
whole range of seed points since the perimeter line-chains may well cross either themselves
or each other thus producing several different closed shapes to be filled."

The host rasterises the boundary exactly as the terminal will (``vector``), finds the
4-connected pieces of the pixels left free (the way the firmware filler spreads) and takes
one seed per piece that does not reach the window's edge, at its deepest pixel.  So each
seed is off the boundary and the filler, stopped by exactly those boundary pixels, fills
exactly that piece: no leak, and no enclosed piece missed.  Pieces one pixel deep that the
rasterised lines pinch off at a crossing are kept only if the winding or the even-odd rule
puts them inside: a shallow piece of a face with winding number 0 is left to the boundary,
drawn in the fill colour (pieces two pixels deep or more are always filled).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.kas.paint import vector

DEEP = 6  # chamfer units (3 a pixel): two pixels from the wall is a real face, not a pocket


@dataclass
class Faces:
    """The free pieces of a wall map whose [0, 0] is area pixel ``origin``."""

    labels: np.ndarray
    n: int
    best: np.ndarray
    depth: np.ndarray
    bounded: np.ndarray  # (n + 1,) bool
    origin: tuple[int, int]

    def seed(self, k: int) -> tuple[int, int]:
        w = self.labels.shape[1]
        y, x = divmod(int(self.best[k]), w)
        return x + self.origin[0], y + self.origin[1]

    def label_at(self, x: int, y: int) -> int:
        lx, ly = x - self.origin[0], y - self.origin[1]
        h, w = self.labels.shape
        if not (0 <= lx < w and 0 <= ly < h):
            return -1
        return int(self.labels[ly, lx])


def window(polys: list[np.ndarray]) -> tuple[np.ndarray, tuple[int, int]]:
    """A wall map just big enough for ``polys`` (area pixels) plus a free 1-pixel margin."""
    allp = np.concatenate(polys)
    x0, y0 = allp.min(axis=0) - 1
    x1, y1 = allp.max(axis=0) + 1
    wall = np.zeros((int(y1 - y0 + 1), int(x1 - x0 + 1)), dtype=np.uint8)
    for p in polys:
        vector.stamp(wall, p - (x0, y0))
    return wall, (int(x0), int(y0))


def faces(polys: list[np.ndarray]) -> Faces:
    wall, origin = window(polys)
    from camlab88.apps.kas.paint import kernels  # numba: imported on first use

    labels, n, best, depth = kernels.components(wall)
    edge = np.unique(np.concatenate([labels[0], labels[-1], labels[:, 0], labels[:, -1]]))
    bounded = np.ones(n + 1, dtype=bool)
    bounded[edge] = False
    bounded[0] = False
    return Faces(labels, n, best, depth, bounded, origin)


def winding(poly: np.ndarray, x: float, y: float) -> tuple[int, int]:
    """(winding number, crossing count) of the closed polygon around (x, y)."""
    a, b = poly[:-1].astype(np.float64), poly[1:].astype(np.float64)
    up = (a[:, 1] <= y) & (b[:, 1] > y)
    down = (a[:, 1] > y) & (b[:, 1] <= y)
    cross = (b[:, 0] - a[:, 0]) * (y - a[:, 1]) - (x - a[:, 0]) * (b[:, 1] - a[:, 1])
    left_up, left_down = int(np.sum(up & (cross > 0))), int(np.sum(down & (cross < 0)))
    return left_up - left_down, left_up + left_down


def shape_seeds(poly: np.ndarray) -> list[tuple[int, int]]:
    """One seed per closed piece of the closed polygon ``poly`` (area pixels, (n, 2))."""
    f = faces([poly])
    out = []
    for k in range(1, f.n + 1):
        if not f.bounded[k]:
            continue
        sx, sy = f.seed(k)
        if f.depth[k] < DEEP:
            wn, crossings = winding(poly, sx, sy)
            if wn == 0 and crossings % 2 == 0:
                continue  # a pocket pinched off outside the shape at a crossing
        out.append((sx, sy))
    return out
