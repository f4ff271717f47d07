"""Host-side drawing of the table picture: convex polygons clipped to the near plane,
projected, and filled by the even-odd rule at pixel centres (the same rule as the Rainbow's
own polygon op), into a pad-sized array that one put_pixels sends.  Measured: filling a
screen-sized quad this way and sending it costs well under a millisecond, the device's
scan-line polygon op about 10 ms (docs/perf/camera.md)."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.camera.projection import Camera, camera_basis, scale_px

NEAR_CLIP_M = 1e-2  # table faces are clipped 1 cm in front of the observer


def to_camera(camera: Camera, pts: np.ndarray) -> np.ndarray:
    """(..., 3) world points -> (..., 3) camera space: (right, up, depth)."""
    right, up, forward = camera_basis(camera)
    return (pts - camera.observer) @ np.stack([right, up, forward], axis=1)


def clip_near(poly: np.ndarray, near: float = NEAR_CLIP_M) -> np.ndarray:
    """Sutherland-Hodgman against depth >= near: (k, 3) camera-space corners in order."""
    out = []
    k = len(poly)
    for i in range(k):
        a, b = poly[i], poly[(i + 1) % k]
        ina, inb = a[2] >= near, b[2] >= near
        if ina:
            out.append(a)
        if ina != inb:
            t = (near - a[2]) / (b[2] - a[2])
            out.append(a + t * (b - a))
    return np.array(out).reshape(-1, 3)


def project_camera_space(pts: np.ndarray, k: float, width: int, height: int) -> np.ndarray:
    xy = np.empty((len(pts), 2))
    xy[:, 0] = width / 2.0 + k * pts[:, 0] / pts[:, 2]
    xy[:, 1] = height / 2.0 - k * pts[:, 1] / pts[:, 2]
    return xy


def fill_convex(img: np.ndarray, xy: np.ndarray, value: int) -> None:
    """Fill the pixels whose centres lie inside the convex polygon `xy` (screen pixels): one
    kernel, since per-face numpy arrays and per-row slices from Python were the host's
    largest cost with the view moving (docs/perf/camera.md)."""
    from camlab88.apps.snooker.visualiser import spans  # numba: imported on first use

    spans.fill_convex(img, xy, value)


def draw_polygons(img: np.ndarray, camera: Camera, faces: list[tuple[np.ndarray, int]]) -> None:
    """World-space convex polygons ((k, 3) corners, value), in order, each clipped to the
    near plane, into `img`."""
    if not faces:
        return
    h, w = img.shape
    k = scale_px(camera, w)
    cam = to_camera(camera, np.stack([c for c, _ in faces]))  # one transform for them all
    for poly, (_, value) in zip(cam, faces):
        if poly[:, 2].min() < NEAR_CLIP_M:
            poly = clip_near(poly)
            if len(poly) < 3:
                continue
        fill_convex(img, project_camera_space(poly, k, w, h), value)
