"""The editing operations of §3.1.1 as pure functions on point arrays and drawings.

Transforms are affine 3x3 matrices so that 'move back' is the exact inverse and 'move
again' an exact repeat, whatever part of the picture the cursors now select.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camlab88.apps.kas.model import Chain

TRANSFORM_KINDS = ("move", "rotate", "reflect", "enlarge", "stretch")


@dataclass(frozen=True)
class Transform:
    """A remembered simple transformation; ``scope`` says what 'move' moved."""

    kind: str
    matrix: np.ndarray  # 3x3, acts on column vectors (x, y, 1)
    params: tuple[float, ...]
    scope: str = "points"  # points | chain | section
    # the points the animator touched (move: from, to; rotate/enlarge/stretch: origin;
    # reflect: the mirror line), offered again by Return at the same prompts
    touched: tuple[tuple[float, float], ...] = ()

    def inverse(self) -> np.ndarray:
        return np.linalg.inv(self.matrix)


def translation(dx: float, dy: float) -> np.ndarray:
    return np.array([[1.0, 0, dx], [0, 1.0, dy], [0, 0, 1.0]])


def about(origin: tuple[float, float], m2: np.ndarray) -> np.ndarray:
    """A 2x2 linear map applied about ``origin``."""
    ox, oy = origin
    m = np.eye(3)
    m[:2, :2] = m2
    return translation(ox, oy) @ m @ translation(-ox, -oy)


def rotation(angle_deg: float, origin: tuple[float, float]) -> np.ndarray:
    a = math.radians(angle_deg)
    c, s = math.cos(a), math.sin(a)
    return about(origin, np.array([[c, -s], [s, c]]))


def reflection(p: tuple[float, float], q: tuple[float, float]) -> np.ndarray:
    dx, dy = q[0] - p[0], q[1] - p[1]
    n = math.hypot(dx, dy)
    if n == 0:
        raise ValueError("the mirror line needs two different points")
    ux, uy = dx / n, dy / n
    m2 = np.array([[2 * ux * ux - 1, 2 * ux * uy], [2 * ux * uy, 2 * uy * uy - 1]])
    return about(p, m2)


def scaling(sx: float, sy: float, origin: tuple[float, float]) -> np.ndarray:
    if sx == 0 or sy == 0:
        raise ValueError("a zero factor would destroy the points (use collapse instead)")
    return about(origin, np.diag([sx, sy]))


def apply(matrix: np.ndarray, pts: np.ndarray) -> np.ndarray:
    return pts @ matrix[:2, :2].T + matrix[:2, 2]


def collapse_to_point(pts: np.ndarray, p: tuple[float, float]) -> np.ndarray:
    return np.broadcast_to(np.asarray(p, dtype=np.float64), pts.shape).copy()


def collapse_to_line(pts: np.ndarray, p: tuple[float, float],
                     q: tuple[float, float]) -> np.ndarray:
    """Project every point onto the straight line through p and q."""
    p_ = np.asarray(p, dtype=np.float64)
    d = np.asarray(q, dtype=np.float64) - p_
    nn = float(d @ d)
    if nn == 0:
        return collapse_to_point(pts, p)
    t = ((pts - p_) @ d) / nn
    return p_ + t[:, None] * d


def deregularise(chain: Chain, lo: int, hi: int, magnitude: float,
                 rng: np.random.Generator) -> tuple[Chain, np.ndarray]:
    """Fractal polyline step (Mandelbrot 1975, §3.1.1): each segment between points lo..hi
    gains a midpoint displaced perpendicular to it by up to ``magnitude`` either way.

    Returns the new chain and, for each old point, its new index."""
    pts, cols = chain.points, chain.colours
    n = len(pts)
    out_p, out_c, new_index = [], [], np.empty(n, dtype=int)
    for i in range(n):
        if lo < i <= hi:
            a, b = pts[i - 1], pts[i]
            d = b - a
            length = math.hypot(*d)
            off = rng.uniform(-magnitude, magnitude)
            mid = (a + b) / 2
            if length > 0:
                mid = mid + off * np.array([-d[1], d[0]]) / length
            out_p.append(mid)
            out_c.append(cols[i])
        new_index[i] = len(out_p)
        out_p.append(pts[i])
        out_c.append(cols[i])
    return Chain(np.array(out_p), np.array(out_c), chain.section), new_index


def circle(centre: tuple[float, float], rim: tuple[float, float],
           segments: int = 36) -> np.ndarray:
    r = math.hypot(rim[0] - centre[0], rim[1] - centre[1])
    a0 = math.atan2(rim[1] - centre[1], rim[0] - centre[0])
    a = a0 + np.linspace(0, 2 * math.pi, segments + 1)
    pts = np.column_stack([centre[0] + r * np.cos(a), centre[1] + r * np.sin(a)])
    pts[-1] = pts[0]  # closed exactly
    return pts


def rectangle(p: tuple[float, float], q: tuple[float, float]) -> np.ndarray:
    return np.array([p, (q[0], p[1]), q, (p[0], q[1]), p], dtype=np.float64)
