"""What to draw for one frame and in which order: the painter's algorithm as thesis 6.4.1
lists it — "start the drawing process with the table legs, then progress to the playing
surface and the shadows of the balls on it, followed by the cushions which are 'behind' the
playing surface, then the balls (from back to front) and finally the cushions and table
edges closest to the observer".

A side of the table (its cushion, rail and apron) is *behind* when the observer is on the
playing side of its cushion face, so the balls are drawn over it; otherwise it is *near*
and drawn over the balls. Faces turned away from the observer are left out; within a group
the farther face goes first. Every backend (truecolour, the Sigma host) draws this list.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.render.lights import Lights
from camlab88.apps.snooker.render.materials import BALL_ALBEDO, SURFACES
from camlab88.apps.snooker.render.scene import Scene
from camlab88.apps.snooker.render.shading import constant_colour, light_terms
from camlab88.apps.snooker.render.shadows import ball_shadow_ellipses, cushion_shadow_polygons
from camlab88.apps.snooker.render.tablemodel import OUTWARD, SIDES, Face, table_faces


@dataclass(frozen=True, eq=False)
class PolygonItem:
    """A constant-shaded face: world vertices (k, 3) and its linear colour."""

    face: Face
    colour: np.ndarray


@dataclass(frozen=True, eq=False)
class ShadowItem:
    """The ball and cushion shadows on the baize. Light l's share of the baize's colour is
    ``removed[l]``; where a shadow of light l covers a pixel by c, c * removed[l] goes."""

    ellipses: np.ndarray  # (m, 7) see shadows.ball_shadow_ellipses
    cushions: list[tuple[int, np.ndarray]]
    removed: np.ndarray  # (lights, 3)


@dataclass(frozen=True, eq=False)
class BallItem:
    ball: int
    centre: np.ndarray
    albedo: np.ndarray


Item = PolygonItem | ShadowItem | BallItem


def _visible(face: Face, eye: np.ndarray) -> bool:
    return float(face.normal @ (eye - face.centre)) > 0.0


def _far_first(faces: list[Face], eye: np.ndarray) -> list[Face]:
    return sorted(faces, key=lambda f: -float(np.linalg.norm(f.centre - eye)))


def side_is_behind(side: str, eye: np.ndarray, hl: float, hw: float) -> bool:
    """True when the observer is on the playing side of that side's cushion face."""
    ox, oy = OUTWARD[side]
    return float(eye[0] * ox + eye[1] * oy) < abs(ox) * hl + abs(oy) * hw


def plan(scene: Scene, row: int, eye: np.ndarray, view_depth: np.ndarray,
         faces: tuple[Face, ...] | None = None) -> list[Item]:
    """The ordered draw list for row ``row`` of the scene, seen from ``eye``.
    ``view_depth`` (22,) orders the balls (depth along the view axis, farthest first)."""
    t = scene.table
    hl, hw = t.length_m / 2.0, t.width_m / 2.0
    lights = scene.lights
    faces = faces if faces is not None else table_faces(t)
    shown = [f for f in faces if _visible(f, eye)]

    def polys(fs: list[Face]) -> list[Item]:
        return [PolygonItem(f, _colour(f, lights)) for f in _far_first(fs, eye)]

    items: list[Item] = polys([f for f in shown if f.group == "leg"])
    items += polys([f for f in shown if f.group == "surface"])
    items += [PolygonItem(f, _colour(f, lights)) for f in shown if f.group == "pocket"]
    items.append(_shadows(scene, row))
    behind = [s for s in SIDES if side_is_behind(s, eye, hl, hw)]
    near = [s for s in SIDES if s not in behind]
    items += polys([f for f in shown if f.side in behind])
    on = np.nonzero(scene.on_table[row])[0]
    for b in sorted(on.tolist(), key=lambda k: (-float(view_depth[k]), k)):
        items.append(BallItem(b, scene.centres[row, b], BALL_ALBEDO[b]))
    items += polys([f for f in shown if f.side in near])
    return items


def _colour(face: Face, lights: Lights) -> np.ndarray:
    return constant_colour(np.array(SURFACES[face.material]), face.centre, face.normal, lights)


def _shadows(scene: Scene, row: int) -> ShadowItem:
    t = scene.table
    on = scene.on_table[row]
    ell = ball_shadow_ellipses(scene.centres[row][on], t.radius, scene.lights.positions)
    cush = cushion_shadow_polygons(t.length_m / 2.0, t.width_m / 2.0, scene.lights.positions)
    removed = np.array(SURFACES["baize"]) * light_terms(np.zeros(3), np.array([0.0, 0, 1]),
                                                        scene.lights)
    return ShadowItem(ell, cush, removed)
