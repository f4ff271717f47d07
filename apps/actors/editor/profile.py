"""The lathe profile being drawn (pure): (radius, height) points bottom to top, in cell
units, edited by screen position in the profile pad.

The actors file wants heights that never decrease (docs/ca_actors.md), so the editor keeps
them so: a new point goes after every point not higher than it, and a dragged point's height
stays between its neighbours'. Positions snap to 1/SNAP of a unit and stay inside the pad.
"""

from __future__ import annotations

import bisect
import math

from camlab88.apps.actors.editor.layout import (
    AXIS_X,
    FLOOR_Y,
    HIT,
    MAX_HEIGHT,
    MAX_POINTS,
    MAX_RADIUS,
    SNAP,
    UNIT,
)

Point = tuple[float, float]


def to_units(px: int, py: int) -> Point:
    """Profile-pad pixel -> (radius, height), snapped and clamped."""
    r = min(max(round((px - AXIS_X) * SNAP / UNIT), 0), math.floor(MAX_RADIUS * SNAP))
    h = min(max(round((FLOOR_Y - py) * SNAP / UNIT), 0), math.floor(MAX_HEIGHT * SNAP))
    return r / SNAP, h / SNAP


def to_pixels(p: Point) -> tuple[int, int]:
    return AXIS_X + round(p[0] * UNIT), FLOOR_Y - round(p[1] * UNIT)


class Profile:
    def __init__(self, points: tuple[Point, ...] = ()) -> None:
        self.points: list[Point] = list(points)

    def as_tuple(self) -> tuple[Point, ...]:
        return tuple(self.points)

    def hit(self, px: int, py: int) -> int | None:
        """The index of the point within HIT pixels of (px, py) (the nearest; the later
        one of two equally near)."""
        best, best_d = None, HIT + 0.5
        for i, p in enumerate(self.points):
            x, y = to_pixels(p)
            d = math.hypot(x - px, y - py)
            if d <= best_d:
                best, best_d = i, d
        return best

    def add(self, px: int, py: int) -> int | None:
        """A new point at (px, py); its index, or None when the profile is full."""
        if len(self.points) >= MAX_POINTS:
            return None
        p = to_units(px, py)
        i = bisect.bisect_right([q[1] for q in self.points], p[1])
        self.points.insert(i, p)
        return i

    def move(self, i: int, px: int, py: int) -> bool:
        """Point i to (px, py); True if it moved."""
        r, h = to_units(px, py)
        if i > 0:
            h = max(h, self.points[i - 1][1])
        if i + 1 < len(self.points):
            h = min(h, self.points[i + 1][1])
        p = (r, h)
        if self.points[i] == p:
            return False
        self.points[i] = p
        return True

    def delete(self, i: int) -> None:
        del self.points[i]

    def clear(self) -> None:
        self.points.clear()
