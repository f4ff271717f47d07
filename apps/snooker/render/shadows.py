"""Shadows on the baize (thesis 6.4.1): per light, each ball's shadow as an ellipse "of
which one axis is the diameter of the ball and the eccentricity and position are related
to the direction from the ball to the light source", and the cushions' shadows.

The ellipse is the shadow a ball casts in light arriving from the light's direction: its
centre is where the ray from the light through the ball's centre meets the baize, its minor
semi-axis the ball's radius (across the light's direction), its major semi-axis
radius / sin(elevation) along the light's horizontal direction (elevation = the angle of
the light above the horizontal, seen from the ball's centre).
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.render.clip import clip_box
from camlab88.apps.snooker.render.tablemodel import CUSHION_H_M, OUTWARD, SIDES


def ball_shadow_ellipses(centres: np.ndarray, radius: float,
                         light_positions: np.ndarray) -> np.ndarray:
    """(n, 3) ball centres x (m, 3) lights -> (n * m, 7) rows (cx, cy, ux, uy, a, b, light):
    centre on the baize, unit major-axis direction, semi-axes a (major) and b = radius."""
    rows = []
    for li, lp in enumerate(np.asarray(light_positions, dtype=np.float64)):
        d = centres - lp  # from the light through each centre
        drop = lp[2] - centres[:, 2]
        ok = drop > 1e-9  # a light below a ball's centre casts no shadow on the baize
        t = np.where(ok, centres[:, 2] / np.where(ok, drop, 1.0), 0.0)
        ground = centres[:, :2] + d[:, :2] * t[:, None]
        horiz = np.linalg.norm(d[:, :2], axis=1)
        u = np.where(horiz[:, None] > 1e-12, d[:, :2] / np.maximum(horiz, 1e-12)[:, None],
                     np.array([1.0, 0.0]))
        sin_e = drop / np.linalg.norm(d, axis=1)
        a = radius / np.maximum(sin_e, 1e-6)
        for k in np.nonzero(ok)[0]:
            rows.append((ground[k, 0], ground[k, 1], u[k, 0], u[k, 1], a[k], radius, li))
    return np.array(rows, dtype=np.float64).reshape(-1, 7)


def cushion_shadow_polygons(hl: float, hw: float,
                            light_positions: np.ndarray) -> list[tuple[int, np.ndarray]]:
    """Per light, each cushion's shadow on the baize: the strip between the foot of the
    cushion face and the shadow of its nose (height CUSHION_H_M), when that falls on the
    playing side, clipped to the playing area. Returns (light, (k, 3) ground polygon)."""
    out = []
    for li, lp in enumerate(np.asarray(light_positions, dtype=np.float64)):
        if lp[2] <= CUSHION_H_M:
            continue
        for s in SIDES:
            ox, oy = OUTWARD[s]
            tx, ty = -oy, ox
            edge = abs(ox) * hl + abs(oy) * hw
            half = abs(tx) * hl + abs(ty) * hw
            foot = [np.array([ox * edge + tx * k * half, oy * edge + ty * k * half])
                    for k in (-1.0, 1.0)]
            t = CUSHION_H_M / (lp[2] - CUSHION_H_M)
            tip = [f + (f - lp[:2]) * t for f in foot]
            inward = [-(p[0] * ox + p[1] * oy - edge) for p in tip]  # > 0: on the baize
            if max(inward) <= 0:
                continue
            poly = clip_box(np.array([foot[0], foot[1], tip[1], tip[0]]), hl, hw)
            if len(poly) >= 3:
                out.append((li, np.hstack([poly, np.zeros((len(poly), 1))])))
    return out
