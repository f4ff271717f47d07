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
the order is deterministic.  The scan is a plain loop compiled with numba (the benchmark
shows it pays), in kernels.py with the frame loop that calls it; the same Python function
is physics' path for tables without a tabulated speed curve.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.kernels import (  # noqa: F401 - the scan, named here too
    NO_EVENT,
    scan,
    scan_python,
)


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
