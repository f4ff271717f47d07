"""The billiard table as flat polygons in the table frame (thesis 6.4.1).

Table frame (camera/space.py): metres, origin the centre of the playing surface, +x towards
the top cushion, +y towards the left cushion seen from baulk, +z up; the baize is z = 0. The
playing surface, the pockets on it, the cushions (front face and top), the wooden surround
(rail top and the apron below it: the "table edges") and six legs. Cushion and rail sizes
are reconstructed (the thesis gives none; docs/fidelity/snooker.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from camlab88.apps.snooker.render.clip import clip_box
from camlab88.apps.snooker.table import Table

CUSHION_W_M = 0.05
CUSHION_H_M = 0.0365  # nose height, about 0.7 of a ball diameter
RAIL_W_M = 0.10
APRON_M = 0.20  # depth of the wooden side below the cushion top
FLOOR_Z_M = -0.82
LEG_M = 0.11
SIDES = ("baulk", "top", "left", "right")
OUTWARD = {"baulk": (-1.0, 0.0), "top": (1.0, 0.0), "left": (0.0, 1.0), "right": (0.0, -1.0)}


@dataclass(frozen=True, eq=False)
class Face:
    """One planar convex polygon: vertices (k, 3) anticlockwise seen from its front."""

    name: str
    group: str  # "leg", "surface", "pocket", "cushion", "rail"
    side: str  # one of SIDES, or "" for the surface, pockets and legs
    vertices: np.ndarray
    normal: np.ndarray
    material: str

    @property
    def centre(self) -> np.ndarray:
        return self.vertices.mean(axis=0)


def _face(name: str, group: str, side: str, pts: list[tuple[float, float, float]],
          material: str) -> Face:
    v = np.array(pts, dtype=np.float64)
    n = np.cross(v, np.roll(v, -1, axis=0)).sum(axis=0)  # Newell: robust to collinear points
    return Face(name, group, side, v, n / np.linalg.norm(n), material)


def _ring_trapezoid(side: str, hl: float, hw: float, d0: float, d1: float,
                    z: float) -> list[tuple[float, float, float]]:
    """The mitred strip of one side between the rectangles grown by d0 and by d1, at z."""
    ox, oy = OUTWARD[side]
    tx, ty = -oy, ox  # anticlockwise along the side, seen from above
    half_in = abs(tx) * hl + abs(ty) * hw
    edge = abs(ox) * hl + abs(oy) * hw

    def p(d: float, s: float) -> tuple[float, float, float]:
        return (ox * (edge + d) + tx * s * (half_in + d),
                oy * (edge + d) + ty * s * (half_in + d), z)

    return [p(d0, -1), p(d1, -1), p(d1, 1), p(d0, 1)]


def _vertical(side: str, hl: float, hw: float, d: float, z0: float, z1: float,
              facing_out: bool) -> list[tuple[float, float, float]]:
    ox, oy = OUTWARD[side]
    tx, ty = -oy, ox
    half = abs(tx) * hl + abs(ty) * hw + d
    edge = abs(ox) * hl + abs(oy) * hw + d
    a = (ox * edge - tx * half, oy * edge - ty * half)
    b = (ox * edge + tx * half, oy * edge + ty * half)
    pts = [(a[0], a[1], z0), (b[0], b[1], z0), (b[0], b[1], z1), (a[0], a[1], z1)]
    return pts if facing_out else pts[::-1]


def _pocket(name: str, cx: float, cy: float, r: float, hl: float, hw: float) -> Face | None:
    """A pocket's mouth on the baize: its circle, clipped to the playing surface."""
    ang = np.linspace(0.0, 2 * math.pi, 24, endpoint=False)
    ring = np.stack([cx + r * np.cos(ang), cy + r * np.sin(ang)], axis=1)
    pts = clip_box(ring, hl, hw)
    if len(pts) < 3:
        return None
    return _face(f"pocket {name}", "pocket", "", [(x, y, 0.0) for x, y in pts], "pocket")


@lru_cache(maxsize=8)
def table_faces(table: Table) -> tuple[Face, ...]:
    """Every face of the table model (the same objects for equal tables)."""
    hl, hw = table.length_m / 2.0, table.width_m / 2.0
    faces = [_face("playing surface", "surface", "",
                   [(-hl, -hw, 0.0), (hl, -hw, 0.0), (hl, hw, 0.0), (-hl, hw, 0.0)], "baize")]
    for p in table.pockets:
        cx, cy = p.centre
        f = _pocket(p.name, cx - hl, cy - hw, p.width / 2.0 + 0.01, hl, hw)
        if f is not None:
            faces.append(f)
    top = CUSHION_H_M
    for s in SIDES:
        faces.append(_face(f"{s} cushion face", "cushion", s,
                           _vertical(s, hl, hw, 0.0, 0.0, top, False), "cushion"))
        faces.append(_face(f"{s} cushion top", "cushion", s,
                           _ring_trapezoid(s, hl, hw, 0.0, CUSHION_W_M, top), "cushion"))
        faces.append(_face(f"{s} rail", "rail", s,
                           _ring_trapezoid(s, hl, hw, CUSHION_W_M, CUSHION_W_M + RAIL_W_M, top),
                           "wood"))
        faces.append(_face(f"{s} apron", "rail", s,
                           _vertical(s, hl, hw, CUSHION_W_M + RAIL_W_M, -APRON_M, top, True),
                           "wood"))
    return tuple(faces) + _legs(hl, hw)


def _legs(hl: float, hw: float) -> tuple[Face, ...]:
    out = []
    h = LEG_M / 2.0
    inset = 0.12
    for k, (x, y) in enumerate((sx * (hl - inset), sy * (hw - inset))
                               for sx in (-1.0, 0.0, 1.0) for sy in (-1.0, 1.0)):
        corners = [(x - h, y - h), (x + h, y - h), (x + h, y + h), (x - h, y + h)]
        for i in range(4):
            (ax, ay), (bx, by) = corners[i], corners[(i + 1) % 4]
            out.append(_face(f"leg {k + 1}.{i + 1}", "leg", "",
                             [(ax, ay, FLOOR_Z_M), (bx, by, FLOOR_Z_M), (bx, by, -APRON_M),
                              (ax, ay, -APRON_M)], "leg"))
    return tuple(out)
