"""Colour arithmetic for palettes and their measurement: linear RGB (sRGB primaries, D65)
to CIE L*a*b*, and the CIE76 colour difference."""

from __future__ import annotations

import numpy as np

_RGB_TO_XYZ = np.array([[0.4124564, 0.3575761, 0.1804375],
                        [0.2126729, 0.7151522, 0.0721750],
                        [0.0193339, 0.1191920, 0.9503041]])
_WHITE = _RGB_TO_XYZ.sum(axis=1)
_EPS = (6.0 / 29.0) ** 3


def lab(linear: np.ndarray) -> np.ndarray:
    """(..., 3) linear RGB 0..1 -> (..., 3) L*a*b*."""
    xyz = np.clip(np.asarray(linear, dtype=np.float64), 0.0, 1.0) @ _RGB_TO_XYZ.T / _WHITE
    f = np.where(xyz > _EPS, np.cbrt(xyz), xyz / (3 * (6.0 / 29.0) ** 2) + 4.0 / 29.0)
    return np.stack([116.0 * f[..., 1] - 16.0, 500.0 * (f[..., 0] - f[..., 1]),
                     200.0 * (f[..., 1] - f[..., 2])], axis=-1)


def delta_e(a_lab: np.ndarray, b_lab: np.ndarray) -> np.ndarray:
    """CIE76 difference of two L*a*b* arrays."""
    return np.linalg.norm(np.asarray(a_lab) - np.asarray(b_lab), axis=-1)


def lab_to_linear(lab_values: np.ndarray) -> np.ndarray:
    """(N, 3) L*a*b* -> (N, 3) linear RGB (unclipped)."""
    lv = np.asarray(lab_values, dtype=np.float64)
    fy = (lv[:, 0] + 16.0) / 116.0
    f = np.stack([fy + lv[:, 1] / 500.0, fy, fy - lv[:, 2] / 200.0], axis=1)
    d = 6.0 / 29.0
    xyz = np.where(f > d, f ** 3, 3 * d * d * (f - 4.0 / 29.0)) * _WHITE
    return xyz @ np.linalg.inv(_RGB_TO_XYZ).T
