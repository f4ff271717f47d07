"""The billiard table the visualiser draws (thesis §6.3.2: "the billiard table has no
corner pockets since these are unnecessary details"): axis-aligned boxes in the default
space -- the bed under the cloth, four cushions and four wooden rails -- each face one
constant colour.  Sizes beyond the playing surface are reconstructed (docs/fidelity).

Hidden surfaces: the faces of one box that face the observer never overlap each other;
between boxes the painter's order comes from a separating plane (two disjoint boxes always
have one along an axis: a box cannot be hidden by one on the far side of such a plane, so
a box is drawn first only if the observer is beyond every plane that separates it from
another)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.table import Table

CUSHION_W_M = 0.05  # cushion face to rail (2 in)
CUSHION_H_M = 0.037  # cushion top above the cloth (~0.7 of a ball's diameter)
RAIL_W_M = 0.10
BED_M = 0.03  # slate and cloth under the playing surface
APRON_M = 0.20  # the rails' outer faces reach this far below the cloth

# Table pad values (3 bits): 0 is transparent (the background shows through).
CLOTH, CUSHION_TOP, CUSHION_FACE, RAIL_TOP, RAIL_SIDE, UNDERSIDE = 1, 2, 3, 4, 5, 6


@dataclass(frozen=True)
class Box:
    lo: tuple[float, float, float]
    hi: tuple[float, float, float]
    top: int
    side: int
    bottom: int = UNDERSIDE

    def faces(self, observer: np.ndarray) -> list[tuple[np.ndarray, int]]:
        """The faces turned towards the observer: (4, 3) corners and a pad value each."""
        lo, hi = np.array(self.lo), np.array(self.hi)
        out = []
        for axis in range(3):
            for high in (False, True):
                plane = hi[axis] if high else lo[axis]
                if (observer[axis] > plane) != high or observer[axis] == plane:
                    continue
                value = (self.top if high else self.bottom) if axis == 2 else self.side
                out.append((_quad(lo, hi, axis, plane), value))
        return out


def _quad(lo: np.ndarray, hi: np.ndarray, axis: int, plane: float) -> np.ndarray:
    a, b = [k for k in range(3) if k != axis]
    q = np.empty((4, 3))
    for i, (ua, ub) in enumerate(((0, 0), (1, 0), (1, 1), (0, 1))):
        q[i, axis] = plane
        q[i, a] = hi[a] if ua else lo[a]
        q[i, b] = hi[b] if ub else lo[b]
    return q


def boxes(table: Table) -> list[Box]:
    hx, hy = table.length_m / 2, table.width_m / 2
    cx, cy = hx + CUSHION_W_M, hy + CUSHION_W_M
    rx, ry = cx + RAIL_W_M, cy + RAIL_W_M
    h = CUSHION_H_M
    out = [Box((-hx, -hy, -BED_M), (hx, hy, 0.0), CLOTH, CLOTH)]
    for s in (-1, 1):  # long cushions and rails run the full length; the ends fit between
        out.append(Box(_lh(s, -cx, hy, cy, 0.0)[0], _lh(s, cx, hy, cy, h)[1], CUSHION_TOP,
                       CUSHION_FACE))
        out.append(Box(_lh(s, -rx, cy, ry, -APRON_M)[0], _lh(s, rx, cy, ry, h)[1], RAIL_TOP,
                       RAIL_SIDE))
        out.append(Box(*_end(s, hx, cx, -hy, hy, 0.0, h), CUSHION_TOP, CUSHION_FACE))
        out.append(Box(*_end(s, cx, rx, -cy, cy, -APRON_M, h), RAIL_TOP, RAIL_SIDE))
    return out


def _lh(s: int, x: float, inner: float, outer: float,
        z: float) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """Corners of a long side (y = +-inner..outer) box, as (lo, hi) with x and z given."""
    ylo, yhi = (inner, outer) if s > 0 else (-outer, -inner)
    return (x, ylo, z), (x, yhi, z)


def _end(s: int, inner: float, outer: float, ylo: float, yhi: float, zlo: float,
         zhi: float) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    xlo, xhi = (inner, outer) if s > 0 else (-outer, -inner)
    return (xlo, ylo, zlo), (xhi, yhi, zhi)


def painter_order(bs: list[Box], observer: np.ndarray) -> list[Box]:
    """Boxes far to near: a box is drawn only after every box that could hide behind it."""
    left = list(range(len(bs)))
    order: list[Box] = []
    while left:
        pick = next((i for i in left if not any(_before(bs[j], bs[i], observer)
                                                for j in left if j != i)), left[0])
        left.remove(pick)
        order.append(bs[pick])
    return order


def _before(a: Box, b: Box, o: np.ndarray) -> bool:
    """True if `a` must be drawn before `b`: `b` may hide `a`.  It can only if the observer
    is on b's side of every plane that separates them (one plane with the observer on a's
    side, or in it, proves that b cannot hide a)."""
    separated = False
    for k in range(3):
        if a.hi[k] <= b.lo[k]:  # any plane in the gap separates: b must be beyond them all
            separated = True
            if not o[k] > b.lo[k]:
                return False
        elif b.hi[k] <= a.lo[k]:
            separated = True
            if not o[k] < b.hi[k]:
                return False
    return separated
