"""Velocity and spin arrows (§6.2.2, fig 6.6) as pure screen geometry.

A velocity arrow runs from the ball's centre to the cursor: its length is the speed
(``PX_PER_M_S`` pixels for 1 m/s), and a dotted extension carries the line on so a short
arrow can still be aimed accurately. The spin arrow lies along the velocity arrow: moving
the mouse up gives top spin (forward), down gives back spin (backward).
"""

from __future__ import annotations

import math

from camlab88.apps.snooker.program.layout import TableView

PX_PER_M_S = 40.0  # a 5 m/s break-off is a 200-pixel arrow
SPIN_PX_PER_M_S = 60.0
DOT_GAP = 6
EXTENSION_PX = 900
HEAD_PX = 7

Point = tuple[float, float]
Segment = tuple[int, int, int, int]


def velocity_from_arrow(view: TableView, start: Point, end: Point) -> tuple[float, float]:
    """Screen arrow (pixels) -> model velocity (m/s)."""
    dx, dy = end[0] - start[0], end[1] - start[1]
    vx, vy = view.vector_to_table(dx, dy)
    k = view.scale / PX_PER_M_S
    return (vx * k, vy * k)


def arrow_end(view: TableView, start: Point, velocity: tuple[float, float]) -> Point:
    """Where the arrow of a model velocity ends on the screen."""
    dx, dy = view.vector_to_screen(*velocity)
    k = PX_PER_M_S / view.scale
    return (start[0] + dx * k, start[1] + dy * k)


def spin_from_drag(dy_px: float) -> float:
    """Mouse moved dy pixels (screen, down positive) -> spin in m/s (+ top, - back)."""
    return -dy_px / SPIN_PX_PER_M_S


def spin_arrow(start: Point, end: Point, spin: float) -> Segment | None:
    """The spin arrow along the velocity arrow's line (backwards for back spin)."""
    dx, dy = end[0] - start[0], end[1] - start[1]
    n = math.hypot(dx, dy)
    if n == 0 or spin == 0:
        return None
    k = spin * SPIN_PX_PER_M_S / n
    return (_r(start[0]), _r(start[1]), _r(start[0] + dx * k), _r(start[1] + dy * k))


def arrow_segments(start: Point, end: Point) -> list[Segment]:
    """The shaft and the two barbs of the head."""
    sx, sy, ex, ey = start[0], start[1], end[0], end[1]
    out = [(_r(sx), _r(sy), _r(ex), _r(ey))]
    n = math.hypot(ex - sx, ey - sy)
    if n >= 3:
        ux, uy = (ex - sx) / n, (ey - sy) / n
        for side in (1, -1):
            hx = ex - HEAD_PX * (ux * 0.866 - side * uy * 0.5)
            hy = ey - HEAD_PX * (uy * 0.866 + side * ux * 0.5)
            out.append((_r(ex), _r(ey), _r(hx), _r(hy)))
    return out


def dotted_extension(start: Point, end: Point,
                     length: float = EXTENSION_PX) -> list[tuple[int, int]]:
    """Dots continuing the arrow's line beyond its end (fig 6.6)."""
    dx, dy = end[0] - start[0], end[1] - start[1]
    n = math.hypot(dx, dy)
    if n == 0:
        return []
    ux, uy = dx / n, dy / n
    return [(_r(end[0] + ux * d), _r(end[1] + uy * d))
            for d in range(DOT_GAP, int(length), DOT_GAP)]


def dotted_path(points: list[Point]) -> list[tuple[int, int]]:
    """Dots every DOT_GAP pixels along a polyline (the aimed path, §6.2.2)."""
    out: list[tuple[int, int]] = []
    carry = 0.0
    for (ax, ay), (bx, by) in zip(points, points[1:]):
        n = math.hypot(bx - ax, by - ay)
        d = carry
        while d <= n:
            t = d / n if n else 0.0
            out.append((_r(ax + (bx - ax) * t), _r(ay + (by - ay) * t)))
            d += DOT_GAP
        carry = d - n
    return out


def _r(v: float) -> int:
    return math.floor(v + 0.5)
