"""The perspective the renderer draws with: the camera's projection, as a pinhole.

Rendering needs the inverse too (a ray through every pixel, for shadows on the baize and the
light and eye directions across a surface), so the camera of
``camlab88.apps.snooker.camera.projection`` is turned into its basis, focal length in pixels
and picture centre. Projecting through the ``Pinhole`` gives the same pixels as ``project``
(tests/snooker_render/test_pinhole.py), so ball centres land where the visualiser puts them
(thesis 6.4: "the view produced should agree exactly with the view predicted as part of the
camera definition stage").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.camera.projection import (
    NEAR_M,
    Camera,
    camera_basis,
    pixels_per_metre_at,
    project,
)

__all__ = ["NEAR_M", "Pinhole"]


@dataclass(frozen=True, eq=False)
class Pinhole:
    """Observer, unit basis (right, up, forward), focal length in pixels, picture size."""

    camera: Camera
    observer: np.ndarray
    right: np.ndarray
    up: np.ndarray
    forward: np.ndarray
    focal_px: float
    width: int
    height: int

    @classmethod
    def of(cls, observer: np.ndarray, viewpoint: np.ndarray, focal_mm: float, width: int,
           height: int) -> Pinhole:
        cam = Camera(np.asarray(observer, dtype=np.float64),
                     np.asarray(viewpoint, dtype=np.float64), float(focal_mm))
        right, up, forward = (np.asarray(v, dtype=np.float64) for v in camera_basis(cam))
        f = float(pixels_per_metre_at(cam, 1.0, width))
        return cls(cam, cam.observer, right, up, forward, f, width, height)

    def to_camera(self, points: np.ndarray) -> np.ndarray:
        """(N, 3) world -> (N, 3) camera coordinates (right, up, depth)."""
        d = np.asarray(points, dtype=np.float64) - self.observer
        return np.stack([d @ self.right, d @ self.up, d @ self.forward], axis=-1)

    def project(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(N, 3) world -> (xy (N, 2) pixels, depth (N,), visible (N,)): the camera's
        ``project`` itself, so the renderer and the visualiser agree to the bit."""
        return project(self.camera, np.asarray(points, dtype=np.float64), self.width,
                       self.height)

    def rays(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Unnormalised ray directions (..., 3) through pixel positions (x right, y down)."""
        a = (np.asarray(x, dtype=np.float64) - self.width / 2.0) / self.focal_px
        b = (self.height / 2.0 - np.asarray(y, dtype=np.float64)) / self.focal_px
        return (self.forward + a[..., None] * self.right + b[..., None] * self.up)

    def ground(self, x: np.ndarray, y: np.ndarray, z: float = 0.0) -> tuple[np.ndarray,
                                                                              np.ndarray]:
        """Where the rays through (x, y) meet the plane height ``z``: (points (..., 3), hit)."""
        d = self.rays(x, y)
        dz = d[..., 2]
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (z - self.observer[2]) / dz
        hit = np.isfinite(t) & (t > 0)
        t = np.where(hit, t, 0.0)
        return self.observer + t[..., None] * d, hit
