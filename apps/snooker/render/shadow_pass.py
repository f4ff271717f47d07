"""The shadows on the baize as a dimming of the picture, shared by the truecolour renderer
and the Sigma host (thesis 6.4.1: per light, ball ellipses and the cushions' shadows)."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.render import kernels as K
from camlab88.apps.snooker.render.frame import (
    FrameGeometry,
    camera_params,
    clip_project,
    shadow_boxes,
)
from camlab88.apps.snooker.render.painter import ShadowItem


def shadow_occlusion(g: FrameGeometry, item: ShadowItem, height: int, width: int
                     ) -> tuple[np.ndarray, int, int]:
    """(occ (lights, h, w, 1), x0, y0): how much of each light's share of the baize is
    shadowed, over the box of the screen (from pixel (x0, y0)) that the shadows can reach."""
    polys = [(li, xy) for li, poly in item.cushions
             if (xy := clip_project(g.pin, poly)) is not None]
    ell, boxes = shadow_boxes(g.pin, item.ellipses)
    lo = [boxes[:, :2].min(axis=0)] if len(boxes) else []
    hi = [boxes[:, 2:].max(axis=0) + 1] if len(boxes) else []
    for _li, xy in polys:
        lo.append(np.floor(xy.min(axis=0)) - 1)
        hi.append(np.floor(xy.max(axis=0)) + 2)
    if not lo:
        return np.zeros((len(item.removed), 0, 0, 1)), 0, 0
    x0, y0 = (max(int(v), 0) for v in np.min(lo, axis=0))
    x1, y1 = int(min(np.max(hi, axis=0)[0], width)), int(min(np.max(hi, axis=0)[1], height))
    occ = np.zeros((len(item.removed), max(y1 - y0, 0), max(x1 - x0, 0), 1))
    if occ.size == 0:
        return occ, x0, y0
    one = np.ones(1)
    for li, xy in polys:
        K.polygon(occ[li], np.ascontiguousarray(xy - (x0, y0)), one)
    if len(ell):
        K.shadows(occ, camera_params(g.pin), ell, boxes, g.half_length, g.half_width,
                  np.int64(x0), np.int64(y0))
    return occ, x0, y0


def apply_shadows(img: np.ndarray, g: FrameGeometry, item: ShadowItem) -> None:
    """Dim ``img`` (H, W, 3 linear) where the shadows fall."""
    occ, x0, y0 = shadow_occlusion(g, item, img.shape[0], img.shape[1])
    if occ.size:
        K.dim(img, occ, np.ascontiguousarray(item.removed), np.int64(x0), np.int64(y0))
