"""One frame of the visualiser as drawing orders (thesis §6.3.2): the table picture (only
when the view changes) and the balls as solid discs in decreasing order of depth.

A ball is a disc centred where its centre projects (apps.snooker.camera.projection), with
its radius projected at its centre's depth, in integer pixels: the Rainbow's circle op
fills the pixels whose centres lie within r of pixel (cx, cy), so cx, cy = the pixel the
projected centre falls in.  A ball is not drawn if the observer is within a radius of it
along the view axis (it would cover the picture or be behind), or if its disc lies wholly
off the picture.  Potted balls are not drawn."""

from __future__ import annotations

import math

import numpy as np

from camlab88.apps.snooker.camera.projection import Camera, pixels_per_metre_at, project
from camlab88.apps.snooker.table import N_BALLS, Table, is_red
from camlab88.apps.snooker.visualiser import raster, table_model

RED_VALUE = 8


def ball_value(ball: int) -> int:
    """Ball pad values: 1 the cue ball, 2..7 yellow..black, 8 every red."""
    return RED_VALUE if is_red(ball) else ball + 1


def table_picture(camera: Camera, table: Table, width: int, height: int) -> np.ndarray:
    img = np.zeros((height, width), dtype=np.uint8)
    order = table_model.painter_order(table_model.boxes(table), camera.observer)
    raster.draw_polygons(img, camera, [f for box in order for f in box.faces(camera.observer)])
    return img


def ball_discs(camera: Camera, centres: np.ndarray, on_table: np.ndarray, radius: float,
               width: int, height: int) -> list[tuple[int, int, int, int]]:
    """(cx, cy, r, value) for every visible ball, farthest first (ties: ball order)."""
    xy, depth, _ = project(camera, centres, width, height)
    r_px = radius * pixels_per_metre_at(camera, np.maximum(depth, 1e-300), width)
    out = []
    for i in sorted(range(N_BALLS), key=lambda i: (-depth[i], i)):
        if not on_table[i] or depth[i] <= radius:
            continue
        cx, cy, r = math.floor(xy[i, 0]), math.floor(xy[i, 1]), int(round(r_px[i]))
        if cx + r < 0 or cy + r < 0 or cx - r >= width or cy - r >= height:
            continue
        out.append((cx, cy, r, ball_value(i)))
    return out
