"""One frame's geometry in screen space, shared by every backend: the pinhole, the draw
list, faces clipped to the near plane and projected, balls' discs, shadow boxes."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.render.painter import Item, plan
from camlab88.apps.snooker.render.pinhole import Pinhole
from camlab88.apps.snooker.render.scene import Scene

NEAR_CLIP_M = 0.01  # faces are cut at 1 cm in front of the observer (nothing behind it shows)


@dataclass(frozen=True, eq=False)
class FrameGeometry:
    pin: Pinhole
    row: int
    items: list[Item]
    ball_xy: np.ndarray  # (22, 2) screen pixels (the camera's (apps/snooker/camera) project)
    ball_depth: np.ndarray  # (22,)
    ball_r_px: np.ndarray  # (22,) radius projected at the centre's depth
    half_length: float  # of the playing surface, metres
    half_width: float


def frame_geometry(scene: Scene, observer: np.ndarray, viewpoint: np.ndarray,
                   focal_mm: float, frame: int, width: int, height: int) -> FrameGeometry:
    pin = Pinhole.of(observer, viewpoint, focal_mm, width, height)
    row = scene.index(frame)
    xy, depth, _vis = pin.project(scene.centres[row])
    safe = np.where(depth > 0, depth, 1.0)
    r_px = np.where(depth > 0, scene.table.radius * pin.focal_px / safe, 0.0)
    t = scene.table
    return FrameGeometry(pin, row, plan(scene, row, pin.observer, depth), xy, depth, r_px,
                         t.length_m / 2.0, t.width_m / 2.0)


def clip_project(pin: Pinhole, vertices: np.ndarray) -> np.ndarray | None:
    """World polygon -> screen polygon (k, 2), cut at NEAR_CLIP_M depth; None if nothing."""
    cam = pin.to_camera(vertices)
    d = cam[:, 2]
    if np.all(d >= NEAR_CLIP_M):
        kept = vertices
    else:
        pts = []
        n = len(vertices)
        for k in range(n):
            p, q = vertices[k], vertices[(k + 1) % n]
            dp, dq = d[k], d[(k + 1) % n]
            if dp >= NEAR_CLIP_M:
                pts.append(p)
            if (dp >= NEAR_CLIP_M) != (dq >= NEAR_CLIP_M):
                pts.append(p + (NEAR_CLIP_M - dp) / (dq - dp) * (q - p))
        if len(pts) < 3:
            return None
        kept = np.array(pts)
    xy, _depth, _vis = pin.project(kept)
    return np.ascontiguousarray(xy, dtype=np.float64)


def camera_params(pin: Pinhole) -> np.ndarray:
    """The kernels' ``cam`` array: observer, right, up, forward, focal_px, width, height."""
    return np.ascontiguousarray(np.concatenate(
        [pin.observer, pin.right, pin.up, pin.forward,
         [pin.focal_px, float(pin.width), float(pin.height)]]), dtype=np.float64)


def shadow_boxes(pin: Pinhole, ellipses: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Screen boxes (i0, j0, i1, j1) of the shadow ellipses; returns (kept rows, boxes)."""
    if len(ellipses) == 0:
        return ellipses, np.zeros((0, 4))
    c, u, a, b = ellipses[:, :2], ellipses[:, 2:4], ellipses[:, 4:5], ellipses[:, 5:6]
    # the ground box round each ellipse (a rotated ellipse reaches sqrt((a ux)^2 + (b uy)^2)
    # along x); its projected corners hold the projected ellipse (projection keeps convexity)
    ex = np.sqrt((a[:, 0] * u[:, 0]) ** 2 + (b[:, 0] * u[:, 1]) ** 2)[:, None]
    ey = np.sqrt((a[:, 0] * u[:, 1]) ** 2 + (b[:, 0] * u[:, 0]) ** 2)[:, None]
    pts = np.stack([c + np.hstack([sx * ex, sy * ey]) for sx in (-1, 1) for sy in (-1, 1)],
                   axis=1)  # (m, 4, 2)
    world = np.concatenate([pts, np.zeros((*pts.shape[:2], 1))], axis=2).reshape(-1, 3)
    xy, depth, vis = pin.project(world)
    xy, vis = xy.reshape(-1, 4, 2), vis.reshape(-1, 4)
    ok = vis.all(axis=1)
    lo = np.floor(xy.min(axis=1)) - 2
    hi = np.floor(xy.max(axis=1)) + 2
    lo = np.maximum(lo, 0)
    hi = np.minimum(hi, [pin.width - 1, pin.height - 1])
    ok &= (lo < hi).all(axis=1) & np.isfinite(xy).all(axis=(1, 2))
    boxes = np.concatenate([lo, hi], axis=1)[ok]
    return np.ascontiguousarray(ellipses[ok]), np.ascontiguousarray(boxes, dtype=np.float64)
