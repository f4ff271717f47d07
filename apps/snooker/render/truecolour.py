"""The `truecolour` renderer: the scene model drawn in 24-bit at any size (no terminal).

``render_frame(scene, view, options)`` is a pure function of its (picklable) arguments, so
frames can be rendered in any process and come out byte-identical (thesis 6.4: the same
picture the Sigma shows, without its 256-colour limit).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.render import kernels as K
from camlab88.apps.snooker.render.balls import ball_params
from camlab88.apps.snooker.render.frame import (
    FrameGeometry,
    camera_params,
    clip_project,
    frame_geometry,
)
from camlab88.apps.snooker.render.gamma import encode_image
from camlab88.apps.snooker.render.materials import BACKGROUND
from camlab88.apps.snooker.render.painter import BallItem, PolygonItem, ShadowItem
from camlab88.apps.snooker.render.scene import Scene
from camlab88.apps.snooker.render.shading import lights_array
from camlab88.apps.snooker.render.shadow_pass import apply_shadows
from camlab88.apps.snooker.render.specks import speck_directions
from camlab88.apps.snooker.render.wood import is_wood, wood_params


@dataclass(frozen=True)
class RenderOptions:
    width: int = 768
    height: int = 512
    specks: bool = True
    shadows: bool = True
    wood: bool = True  # Phong + grain on the wooden surround (beyond the thesis: wood.py)


def render_frame(scene: Scene, view: object, options: RenderOptions | None = None,
                 frame: int | None = None) -> np.ndarray:
    """(H, W, 3) uint8, gamma-encoded, row 0 = top. ``view`` has observer, viewpoint,
    focal_mm and frame (the camera's (apps/snooker/camera) View); ``frame`` overrides view.frame."""
    return encode_image(render_linear(scene, view, options, frame))


def render_linear(scene: Scene, view: object, options: RenderOptions | None = None,
                  frame: int | None = None) -> np.ndarray:
    """(H, W, 3) float64 linear light."""
    o = options or RenderOptions()
    g = frame_geometry(scene, np.asarray(view.observer), np.asarray(view.viewpoint),
                       float(view.focal_mm), int(view.frame if frame is None else frame),
                       o.width, o.height)
    img = np.empty((o.height, o.width, 3), dtype=np.float64)
    img[:] = BACKGROUND
    lights = lights_array(scene.lights)
    for item in g.items:
        if isinstance(item, PolygonItem):
            xy = clip_project(g.pin, item.face.vertices)
            if xy is None:
                continue
            if o.wood and is_wood(item.face):
                K.wood_polygon(img, xy, camera_params(g.pin), wood_params(item.face), lights,
                               np.ascontiguousarray(scene.lights.ambient, dtype=np.float64))
            else:
                K.polygon(img, xy, np.ascontiguousarray(item.colour, dtype=np.float64))
        elif isinstance(item, ShadowItem):
            if o.shadows:
                apply_shadows(img, g, item)
        elif isinstance(item, BallItem):
            draw_ball(img, scene, g, item, lights, o.specks)
    return img


def draw_ball(img: np.ndarray, scene: Scene, g: FrameGeometry, item: BallItem,
              lights: np.ndarray, specks: bool) -> None:
    b = item.ball
    if g.ball_depth[b] <= scene.table.radius + 1e-3:
        return  # behind the observer, or the observer inside the ball
    params = ball_params(g.ball_xy[b], float(g.ball_r_px[b]), item.centre, scene.table.radius,
                         item.albedo, scene.orientations[g.row, b], scene.lights, specks)
    K.ball(img, camera_params(g.pin), params, lights, speck_directions(b))
