"""The visualiser's perspective (thesis §6.3.2, after [Angell 1981]).

The camera is an observer position O and a viewpoint V (the centre of interest) in the
default space (metres, +z up), and a focal length f in mm "scaled as on 35 mm film": the
perspective plane is at distance f, and the picture is 36 mm wide on it, so the horizontal
angle of view across the picture width is 2*atan(18 mm / f).  Pixels are square.

Basis (``camera_basis``):
    forward = (V - O) / |V - O|
    up_ref  = +z, or +x when forward is (anti)parallel to z ("looking straight down, +x is
              up on the screen" -- the camera's roll is fixed by projecting up_ref)
    right   = normalise(forward x up_ref)
    up      = right x forward

Projection of a point P into a W x H picture (``project``), with d = (P - O).forward the
depth along the view axis and k = (f / 18) * (W / 2) the pixels per unit of x/d:
    sx = W/2 + k * ((P - O).right / d)
    sy = H/2 - k * ((P - O).up / d)
Screen coordinates are continuous pixels, x right and y DOWN from the top-left corner of
the picture; pixel (i, j) covers [i, i+1) x [j, j+1), so its centre is at (i+0.5, j+0.5)
and the viewpoint lands on (W/2, H/2), the picture's centre.  A point is visible only if
d > NEAR_M: nothing behind (or at) the observer is drawn.

``pixels_per_metre_at(camera, d, W) = k / d``: a ball's screen radius is its radius
projected at its centre's depth (a reconstruction: a true sphere's outline is a slightly
larger ellipse off-axis; see docs/fidelity/snooker.md).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

FILM_HALF_WIDTH_MM = 18.0  # 35 mm film: a 36 mm wide frame
FILM_W, FILM_H = 768, 512  # the finished picture (§6.4: "only 768 x 512"), which the
# visualiser shows exactly (§6.3.2: "properly clipped to the viewing area")
NEAR_M = 1e-3  # points closer than this along the view axis are not visible
FOCAL_MIN_MM = 8.0  # §6.3.1: "any focal length in the range 8mm to 2000mm"
FOCAL_MAX_MM = 2000.0
_STRAIGHT = 1e-9  # |forward x z| below this counts as looking straight down (or up)


class CameraError(ValueError):
    pass


@dataclass(frozen=True, eq=False)
class Camera:
    """Observer and viewpoint in default-space metres, focal length in mm."""

    observer: np.ndarray
    viewpoint: np.ndarray
    focal_mm: float

    def __init__(self, observer: np.ndarray | tuple[float, float, float],
                 viewpoint: np.ndarray | tuple[float, float, float], focal_mm: float) -> None:
        o = np.asarray(observer, dtype=np.float64).reshape(3)
        v = np.asarray(viewpoint, dtype=np.float64).reshape(3)
        if not (np.all(np.isfinite(o)) and np.all(np.isfinite(v))):
            raise CameraError("observer and viewpoint must be finite")
        if np.array_equal(o, v):
            raise CameraError(f"observer and viewpoint coincide at {tuple(o.tolist())}")
        if not (np.isfinite(focal_mm) and focal_mm > 0):
            raise CameraError(f"focal length {focal_mm!r} mm is not positive")
        object.__setattr__(self, "observer", o)
        object.__setattr__(self, "viewpoint", v)
        object.__setattr__(self, "focal_mm", float(focal_mm))

    def same_view(self, other: Camera) -> bool:
        return (np.array_equal(self.observer, other.observer)
                and np.array_equal(self.viewpoint, other.viewpoint)
                and self.focal_mm == other.focal_mm)


def camera_basis(camera: Camera) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(right, up, forward) unit vectors of the camera, as in the module docstring."""
    d = camera.viewpoint - camera.observer
    forward = d / np.linalg.norm(d)
    up_ref = np.array([0.0, 0.0, 1.0])
    side = np.cross(forward, up_ref)
    if np.linalg.norm(side) < _STRAIGHT:
        side = np.cross(forward, np.array([1.0, 0.0, 0.0]))
    right = side / np.linalg.norm(side)
    up = np.cross(right, forward)
    return right, up, forward


def scale_px(camera: Camera, width: int) -> float:
    """k: screen pixels per unit of (lateral offset / depth)."""
    return camera.focal_mm / FILM_HALF_WIDTH_MM * (width / 2.0)


def project(camera: Camera, points: np.ndarray, width: int,
            height: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(N,3) default-space points -> (xy (N,2) screen pixels, depth (N,), visible (N,))."""
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3) - camera.observer
    right, up, forward = camera_basis(camera)
    depth = p @ forward
    visible = depth > NEAR_M
    safe = np.where(visible, depth, 1.0)  # no division by ~0; invisible points are junk
    k = scale_px(camera, width)
    xy = np.empty((p.shape[0], 2), dtype=np.float64)
    xy[:, 0] = width / 2.0 + k * (p @ right) / safe
    xy[:, 1] = height / 2.0 - k * (p @ up) / safe
    return xy, depth, visible


def pixels_per_metre_at(camera: Camera, depth: np.ndarray | float,
                        width: int) -> np.ndarray | float:
    """Screen pixels per metre, perpendicular to the view axis, at `depth` metres."""
    return scale_px(camera, width) / depth
