"""Clipping a convex 2-D polygon to a box (Sutherland & Hodgman)."""

from __future__ import annotations

import numpy as np


def clip_box(poly: np.ndarray, hl: float, hw: float) -> np.ndarray:
    """Sutherland-Hodgman clip of a 2-D polygon to |x| <= hl, |y| <= hw."""
    pts = [p for p in poly]
    for axis, lim, sign in ((0, hl, 1), (0, hl, -1), (1, hw, 1), (1, hw, -1)):
        res = []
        for k, p in enumerate(pts):
            q = pts[(k + 1) % len(pts)] if pts else p
            pin = sign * p[axis] <= lim + 1e-12
            qin = sign * q[axis] <= lim + 1e-12
            if pin:
                res.append(p)
            if pin != qin:
                t = (lim * sign - p[axis]) / (q[axis] - p[axis])
                res.append(p + t * (q - p))
        pts = res
        if not pts:
            break
    return np.array(pts, dtype=np.float64).reshape(-1, 2)
