"""The shadows on the baize as a dimming of the picture, shared by the truecolour renderer
and the Sigma host (thesis 6.4.1: per light, ball ellipses and the cushions' shadows)."""

from __future__ import annotations

import numpy as np

from apps.snooker.render import kernels as K
from apps.snooker.render.frame import FrameGeometry, camera_params, clip_project, shadow_boxes
from apps.snooker.render.painter import ShadowItem


def shadow_occlusion(g: FrameGeometry, item: ShadowItem, height: int,
                     width: int) -> np.ndarray:
    """(lights, H, W, 1): how much of each light's share of the baize is shadowed."""
    occ = np.zeros((len(item.removed), height, width, 1), dtype=np.float64)
    one = np.ones(1)
    for li, poly in item.cushions:
        xy = clip_project(g.pin, poly)
        if xy is not None:
            K.polygon(occ[li], xy, one)
    ell, boxes = shadow_boxes(g.pin, item.ellipses)
    if len(ell):
        K.shadows(occ, camera_params(g.pin), ell, boxes, g.half_length, g.half_width)
    return occ


def shadow_dimming(g: FrameGeometry, item: ShadowItem, height: int, width: int
                   ) -> tuple[tuple[int, int, int, int] | None, np.ndarray]:
    """((y0, y1, x0, x1) box of the shadowed pixels, (y1-y0, x1-x0, 3) light to take away)."""
    occ = shadow_occlusion(g, item, height, width)
    ys, xs = np.nonzero(occ.any(axis=(0, 3)))
    if len(ys) == 0:
        return None, np.zeros((0, 0, 3))
    y0, y1, x0, x1 = int(ys.min()), int(ys.max()) + 1, int(xs.min()), int(xs.max()) + 1
    return (y0, y1, x0, x1), np.tensordot(occ[:, y0:y1, x0:x1, 0], item.removed,
                                          axes=(0, 0))
