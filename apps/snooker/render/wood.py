"""The wooden surround as the thesis meant it to be (§6.4: "texture mapping ... for the
wooden parts of the table to give the effect of grain ... (ideally this texture should also
be anti-aliased)"; §6.4.1: "the firm intention to add wood texture and Phong shading" —
"in the case of the wooden surround, the surface normal remains constant and it is the
directions to the light source and the observer which change"). Truecolour only: the
period program never had it, and 256 colours could not hold it.

Grain: long stripes along the rail (a plank cut along the log), wobbling, their contrast
faded to the mean colour where a stripe is narrower than a few pixels (anti-aliasing by
clamping the texture's frequencies, not by sampling).
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.render.materials import SURFACES, WOOD_PHONG
from camlab88.apps.snooker.render.tablemodel import OUTWARD, Face

GRAIN_PER_M = 90.0  # stripes per metre across the plank
GRAIN_CONTRAST = 0.35

# layout of the wood parameter row
W_POINT, W_NORMAL, W_U, W_V, W_ALBEDO = 0, 3, 6, 9, 12
W_KA, W_KD, W_KS, W_N, W_FREQ, W_CONTRAST, W_LEN = 15, 16, 17, 18, 19, 20, 21


def is_wood(face: Face) -> bool:
    return face.material == "wood" and face.side != ""


def wood_params(face: Face) -> np.ndarray:
    """The kernel's row for one wooden face: a point on it, its normal, the grain's axes."""
    ox, oy = OUTWARD[face.side]
    u = np.array([-oy, ox, 0.0])  # along the side
    v = np.cross(face.normal, u)
    p = np.zeros(W_LEN)
    p[W_POINT:W_POINT + 3] = face.vertices[0]
    p[W_NORMAL:W_NORMAL + 3] = face.normal
    p[W_U:W_U + 3] = u
    p[W_V:W_V + 3] = v
    p[W_ALBEDO:W_ALBEDO + 3] = SURFACES[face.material]
    p[W_KA], p[W_KD], p[W_KS], p[W_N] = WOOD_PHONG.ka, WOOD_PHONG.kd, WOOD_PHONG.ks, WOOD_PHONG.n
    p[W_FREQ], p[W_CONTRAST] = GRAIN_PER_M, GRAIN_CONTRAST
    return p
