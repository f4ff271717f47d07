"""The perspective of thesis §6.3.2, checked against hand-worked values."""

from __future__ import annotations

import math

import numpy as np
import pytest

from camlab88.apps.snooker.camera.projection import (
    Camera,
    CameraError,
    camera_basis,
    pixels_per_metre_at,
    project,
)

W, H = 768, 576


def test_looking_straight_down_puts_plus_x_up_and_plus_y_left() -> None:
    cam = Camera((0.0, 0.0, 5.0), (0.0, 0.0, 0.0), 50.0)
    right, up, forward = camera_basis(cam)
    assert np.allclose(forward, (0, 0, -1)) and np.allclose(up, (1, 0, 0))
    assert np.allclose(right, (0, -1, 0))
    xy, depth, vis = project(cam, np.array([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 0]]), W, H)
    k = 50 / 18 * 384  # pixels per unit of x/d
    assert np.allclose(xy[0], (384, 288 - k / 5))  # +x: up the screen
    assert np.allclose(xy[1], (384 - k / 5, 288))  # +y: left
    assert np.allclose(xy[2], (384, 288))  # the viewpoint at the picture's centre
    assert np.allclose(depth, 5.0) and vis.all()


@pytest.mark.claim(
    "§6.3.1: focal lengths mean what they do in 35mm photography (50 normal, 28 wide angle, 135 "
    "telephoto); any from 8 to 2000 mm",
    measured="a point at half-angle atan(18/f) lands on the picture's edge, for f = 8 .. 2000 mm",
    verdict="agrees (the 36 mm frame width is reconstructed: docs/fidelity/snooker.md)")
def test_horizontal_angle_of_view_is_2_atan_18_over_f() -> None:
    for f in (8.0, 28.0, 50.0, 135.0, 2000.0):
        cam = Camera((0, 0, 0), (1, 0, 0), f)
        half = math.atan(18.0 / f)
        # A point on the edge of the angle of view lands on the picture's left/right edge.
        pts = np.array([[1, math.tan(half), 0], [1, -math.tan(half), 0]])
        xy, _, _ = project(cam, pts, W, H)
        assert np.allclose(xy[:, 0], (0.0, W)) and np.allclose(xy[:, 1], H / 2)


def test_z_is_up_on_screen_and_roll_follows_z() -> None:
    cam = Camera((-3.0, 0.0, 1.0), (0.0, 0.0, 0.0), 50.0)
    right, up, forward = camera_basis(cam)
    assert up[2] > 0 and abs(right[2]) < 1e-15  # no roll: right stays horizontal
    assert np.allclose(np.cross(right, up), -forward)  # a right-handed screen
    xy, _, _ = project(cam, np.array([[0, 0, 0.5]]), W, H)
    assert xy[0, 1] < H / 2


def test_points_behind_the_observer_are_not_visible() -> None:
    cam = Camera((0, 0, 0), (1, 0, 0), 50)
    _, depth, vis = project(cam, np.array([[-1.0, 0, 0], [0.0, 1, 0], [2.0, 0, 0]]), W, H)
    assert vis.tolist() == [False, False, True] and depth.tolist() == [-1.0, 0.0, 2.0]


def test_pixels_per_metre_matches_projected_offsets() -> None:
    cam = Camera((0.3, -2.0, 1.5), (0.1, 0.2, 0.0), 85.0)
    right, _, forward = camera_basis(cam)
    centre = np.array([0.1, 0.2, 0.0]) + 0.4 * forward
    d = float((centre - cam.observer) @ forward)
    xy, _, _ = project(cam, np.stack([centre, centre + 0.01 * right]), W, H)
    assert math.isclose(xy[1, 0] - xy[0, 0], 0.01 * pixels_per_metre_at(cam, d, W), rel_tol=1e-12)


def test_coincident_observer_and_viewpoint_is_an_error() -> None:
    with pytest.raises(CameraError, match="coincide"):
        Camera((1, 2, 3), (1, 2, 3), 50)
