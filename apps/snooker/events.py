"""Events and their detection: WHEN the next thing happens (`physics` says WHAT it does).

Within a frame every ball moves at constant velocity (§6.2), so every event time is exact:

* ball-cushion: the path is clipped to the cushion face offset by the ball radius,
  lambda = (c - r - b) / V (§6.2), provided the touching point lies on that cushion;
* ball-jaw: the cushion nose beside a pocket is a rounded point; contact is the smaller root
  of |p + lambda v - q|^2 = r^2;
* ball-ball: the smallest positive root of the §6.2 quadratic
  k1 lambda^2 + 2 k2 lambda + k3 = 0, with k1 = V.V, k2 = x.V, k3 = x.x - d^2,
  computed in the cancellation-free form lambda = k3 / (-k2 + sqrt(k2^2 - k1 k3));
* pocket: the ball's centre crosses the mouth line between the two jaws.

The earliest event always comes next; ties go to the first found in a fixed scan order, so
the order is deterministic.  The scan is a plain loop compiled with numba when it is installed (the
benchmark shows it pays); the same Python function is the fallback.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass

import numpy as np

SNOOKER_COMPILE_S = 6.0  # a cold compile of this module's and kernels.py's kernels, measured

try:  # numba is a project dependency, but the model must still work without it
    from camlab88.base.kernel_notice import announce_compiles
    from numba import njit as _njit

    # Cached, so only the first run after install compiles; every kernel here is called with
    # one set of argument types (docs/development.md, "numba's cache").
    def _jit(f):
        return _njit(cache=True, nogil=True)(f)

    announce_compiles("snooker", SNOOKER_COMPILE_S, __name__, "camlab88.apps.snooker.kernels")

    HAVE_NUMBA = True
except ImportError:  # pragma: no cover - exercised only where numba is missing
    HAVE_NUMBA = False

    def _jit(f):
        return f


class EventKind(enum.IntEnum):
    BALL_BALL = 0
    CUSHION = 1
    JAW = 2
    POCKET = 3
    INTERVENTION = 4  # the animator changed something (a significant event, §6.2.2)
    SHOT_END = 5  # all balls at rest: the shot is adjudicated and colours re-spotted


@dataclass(frozen=True)
class Event:
    """What happened at time `t`.  `a` is a ball; `b` is the other ball (BALL_BALL), the
    cushion segment (CUSHION), jaw (JAW) or pocket (POCKET) index, else -1.  `chain` lists
    the balls whose velocity changed (several when a ball hits touching balls)."""

    kind: EventKind
    t: float
    a: int = -1
    b: int = -1
    chain: tuple[int, ...] = ()
    note: str = ""


NO_EVENT = -1


def _scan(pos, vel, active, moving, r, seg, jaws, mouths, horizon):
    """Earliest event within `horizon` seconds: (dt, kind, a, b) or (horizon, -1, -1, -1).

    seg rows: ax ay tx ty nx ny length; jaws rows: x y; mouths rows: ax ay tx ty ox oy width.
    """
    best = horizon
    kind = -1
    ea = -1
    eb = -1
    n = pos.shape[0]
    d2 = 4.0 * r * r
    for i in range(n):
        if not active[i]:
            continue
        px = pos[i, 0]
        py = pos[i, 1]
        vx = vel[i, 0]
        vy = vel[i, 1]
        if moving[i]:
            for k in range(seg.shape[0]):
                vn = vx * seg[k, 4] + vy * seg[k, 5]
                if vn >= 0.0:
                    continue
                s = (px - seg[k, 0]) * seg[k, 4] + (py - seg[k, 1]) * seg[k, 5] - r
                if s < -r:  # centre already behind the face: not this cushion's business
                    continue
                lam = -s / vn
                if lam < 0.0:
                    lam = 0.0
                if lam >= best:
                    continue
                u = (px + vx * lam - seg[k, 0]) * seg[k, 2] + (
                    py + vy * lam - seg[k, 1]
                ) * seg[k, 3]
                if u < 0.0 or u > seg[k, 6]:
                    continue
                best = lam
                kind = 1
                ea = i
                eb = k
            k1 = vx * vx + vy * vy
            for k in range(jaws.shape[0]):
                dx = px - jaws[k, 0]
                dy = py - jaws[k, 1]
                k2 = dx * vx + dy * vy
                if k2 >= 0.0:
                    continue
                k3 = dx * dx + dy * dy - r * r
                disc = k2 * k2 - k1 * k3
                if disc < 0.0:
                    continue
                lam = k3 / (-k2 + math.sqrt(disc)) if k3 > 0.0 else 0.0
                if lam < best:
                    best = lam
                    kind = 2
                    ea = i
                    eb = k
            for k in range(mouths.shape[0]):
                vo = vx * mouths[k, 4] + vy * mouths[k, 5]
                if vo <= 0.0:
                    continue
                s = (px - mouths[k, 0]) * mouths[k, 4] + (py - mouths[k, 1]) * mouths[k, 5]
                lam = -s / vo
                if lam < 0.0:
                    lam = 0.0
                if lam >= best:
                    continue
                u = (px + vx * lam - mouths[k, 0]) * mouths[k, 2] + (
                    py + vy * lam - mouths[k, 1]
                ) * mouths[k, 3]
                if u < -r or u > mouths[k, 6] + r:
                    continue
                best = lam
                kind = 3
                ea = i
                eb = k
        for j in range(i + 1, n):
            if not active[j]:
                continue
            if not (moving[i] or moving[j]):
                continue
            wx = vel[j, 0] - vx
            wy = vel[j, 1] - vy
            x = pos[j, 0] - px
            y = pos[j, 1] - py
            k2 = x * wx + y * wy
            # Not approaching (or slower than physics.APPROACH_TOLERANCE_M_S, which the
            # resolution also ignores): no collision.
            if k2 >= -1e-12 * 2.0 * r:
                continue
            k1 = wx * wx + wy * wy
            k3 = x * x + y * y - d2
            disc = k2 * k2 - k1 * k3
            if disc < 0.0:  # complex roots: they miss
                continue
            lam = k3 / (-k2 + math.sqrt(disc)) if k3 > 0.0 else 0.0
            if lam < best:
                best = lam
                kind = 0
                ea = i
                eb = j
    return best, kind, ea, eb


scan_python = _scan
scan = _jit(_scan)


def table_arrays(table) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The table geometry as the contiguous float arrays `scan` takes."""
    seg = np.array(
        [(s.ax, s.ay, *s.tangent, *s.normal, s.length) for s in table.segments], dtype=np.float64
    )
    jaws = np.array(table.jaws, dtype=np.float64).reshape(-1, 2)
    mouths = []
    for p in table.pockets:
        w = p.width
        mouths.append((p.ax, p.ay, (p.bx - p.ax) / w, (p.by - p.ay) / w, *p.outward, w))
    return seg, jaws, np.array(mouths, dtype=np.float64)


def ball_ball_time(p1, v1, p2, v2, d: float) -> float | None:
    """The §6.2 formula on its own: time until two balls are `d` apart, or None."""
    x, y = p2[0] - p1[0], p2[1] - p1[1]
    vx, vy = v2[0] - v1[0], v2[1] - v1[1]
    k1 = vx * vx + vy * vy
    k2 = x * vx + y * vy
    k3 = x * x + y * y - d * d
    if k1 == 0.0 or k2 >= 0.0:
        return None
    disc = k2 * k2 - k1 * k3
    if disc < 0.0:
        return None
    return max(0.0, k3 / (-k2 + math.sqrt(disc)))
