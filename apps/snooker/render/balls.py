"""The per-ball parameter row the ball kernel reads (kernels.B_* give the layout)."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.render import kernels as K
from camlab88.apps.snooker.render.lights import Lights
from camlab88.apps.snooker.render.materials import BALL_PHONG, SPECK_ALBEDO, Phong
from camlab88.apps.snooker.render.specks import SPECK_RADIUS_RAD

SPECK_MIX = 0.15


def ball_params(xy: np.ndarray, r_px: float, centre: np.ndarray, radius: float,
                albedo: np.ndarray, orientation: np.ndarray, lights: Lights,
                specks: bool = True, phong: Phong = BALL_PHONG) -> np.ndarray:
    b = np.zeros(K.B_LEN, dtype=np.float64)
    b[K.B_CX], b[K.B_CY], b[K.B_RPX] = xy[0], xy[1], r_px
    b[K.B_C:K.B_C + 3] = centre
    b[K.B_R] = radius
    b[K.B_ALBEDO:K.B_ALBEDO + 3] = albedo
    b[K.B_SPECK:K.B_SPECK + 3] = SPECK_ALBEDO
    b[K.B_M:K.B_M + 9] = np.asarray(orientation, dtype=np.float64).reshape(9)
    b[K.B_AMB:K.B_AMB + 3] = lights.ambient
    b[K.B_KA], b[K.B_KD], b[K.B_KS], b[K.B_N] = phong.ka, phong.kd, phong.ks, phong.n
    b[K.B_SPECK_COS] = np.cos(SPECK_RADIUS_RAD)
    b[K.B_SPECK_MIX] = SPECK_MIX if specks else 0.0
    return b
