"""Lighting without the per-pixel loops: constant shading of the flat faces and the Phong
model in numpy (the reference the ball kernel is tested against), thesis 6.4.1."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.render.lights import Lights
from camlab88.apps.snooker.render.materials import Phong


def lights_array(lights: Lights) -> np.ndarray:
    """(n, 6) float64: position, colour — the kernels' form."""
    return np.ascontiguousarray(np.hstack([lights.positions, lights.colours]), dtype=np.float64)


def light_terms(point: np.ndarray, normal: np.ndarray, lights: Lights) -> np.ndarray:
    """(n, 3): each light's diffuse contribution factor max(N.L, 0) * I_l at ``point``."""
    d = lights.positions - point
    d = d / np.linalg.norm(d, axis=1, keepdims=True)
    ndl = np.maximum(d @ normal, 0.0)
    return ndl[:, None] * lights.colours


def constant_colour(albedo: np.ndarray, point: np.ndarray, normal: np.ndarray,
                    lights: Lights, phong: Phong | None = None) -> np.ndarray:
    """Constant shading: ambient + diffuse from every light, evaluated once at ``point``."""
    p = phong or Phong()
    return albedo * (p.ka * lights.ambient + p.kd * light_terms(point, normal, lights).sum(0))


def phong(points: np.ndarray, normals: np.ndarray, eye: np.ndarray, lights: Lights,
          albedo: np.ndarray, p: Phong) -> np.ndarray:
    """(N, 3) points and unit normals -> (N, 3) linear colour, point lights, eye at ``eye``."""
    v = eye - points
    v = v / np.linalg.norm(v, axis=1, keepdims=True)
    out = p.ka * lights.ambient * albedo * np.ones_like(points)
    for lp, li in zip(lights.positions, lights.colours):
        ld = lp - points
        ld = ld / np.linalg.norm(ld, axis=1, keepdims=True)
        ndl = np.sum(normals * ld, axis=1)
        lit = ndl > 0
        r = 2.0 * ndl[:, None] * normals - ld
        rdv = np.maximum(np.sum(r * v, axis=1), 0.0)
        spec = np.where(lit, p.ks * rdv ** p.n, 0.0)
        out += np.where(lit[:, None], p.kd * np.maximum(ndl, 0)[:, None] * albedo
                        + spec[:, None], 0.0) * li
    return out
