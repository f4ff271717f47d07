"""The Phong terms at chosen pixels against a computation done here by hand (thesis 6.4.1:
ambient, diffuse and specular, normals from the sphere, point lights close to the table)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from camlab88.apps.snooker.render import kernels as K
from camlab88.apps.snooker.render.balls import ball_params
from camlab88.apps.snooker.render.frame import camera_params
from camlab88.apps.snooker.render.lights import Lights
from camlab88.apps.snooker.render.materials import Phong
from camlab88.apps.snooker.render.pinhole import Pinhole
from camlab88.apps.snooker.render.shading import lights_array, phong

R = 0.0262
CENTRE = np.array([0.3, -0.2, R])
ALBEDO = np.array([0.7, 0.2, 0.1])
W = H = 96


def _draw(lights: Lights, p: Phong) -> tuple[np.ndarray, Pinhole, np.ndarray]:
    pin = Pinhole.of(np.array([0.3, -0.6, 0.25]), CENTRE, 200.0, W, H)
    xy, depth, _ = pin.project(CENTRE[None])
    r_px = R * pin.focal_px / depth[0]
    img = np.zeros((H, W, 3))
    b = ball_params(xy[0], r_px, CENTRE, R, ALBEDO, np.eye(3), lights, False, p)
    K.ball(img, camera_params(pin), b, lights_array(lights), np.zeros((1, 3)))
    return img, pin, np.array([xy[0, 0], xy[0, 1], r_px])


def _by_hand(pin: Pinhole, disc: np.ndarray, i: int, j: int, lights: Lights,
             p: Phong) -> np.ndarray:
    cx, cy, r = disc
    ux, uy = (i + 0.5 - cx) / r, (cy - (j + 0.5)) / r
    uz = math.sqrt(1 - ux * ux - uy * uy)
    n = ux * pin.right + uy * pin.up - uz * pin.forward  # the sphere's normal at the pixel
    point = CENTRE + R * n
    eye = pin.observer - point
    eye /= np.linalg.norm(eye)
    total = p.ka * lights.ambient * ALBEDO
    for lp, li in zip(lights.positions, lights.colours):
        to_light = (lp - point) / np.linalg.norm(lp - point)
        ndl = n @ to_light
        if ndl <= 0:
            continue
        refl = 2 * ndl * n - to_light
        total = total + (p.kd * ndl * ALBEDO + p.ks * max(refl @ eye, 0.0) ** p.n) * li
    return total


LIGHTS = Lights(np.array([[0.9, 0.4, 1.0], [-0.9, -0.4, 1.0]]),
                np.array([[0.3, 0.3, 0.3], [0.5, 0.4, 0.3]]), np.full(3, 0.2))
PIXELS = ((48, 48), (40, 44), (55, 52), (47, 38))


def test_ambient_only() -> None:
    dark = Lights(LIGHTS.positions, np.zeros((2, 3)), np.full(3, 0.25))
    img, _pin, _disc = _draw(dark, Phong())
    for i, j in PIXELS:
        assert np.allclose(img[j, i], 0.25 * ALBEDO, atol=1e-12)


@pytest.mark.claim(
    "§6.4.1: the Phong model's diffuse, specular and ambient terms for the balls, normals from "
    "the sphere itself",
    measured="each term against a hand computation",
    verdict="agrees")
def test_all_terms_against_a_hand_computation() -> None:
    p = Phong(ka=0.9, kd=0.8, ks=0.6, n=25.0)
    img, pin, disc = _draw(LIGHTS, p)
    for i, j in PIXELS:
        assert np.hypot(i + 0.5 - disc[0], j + 0.5 - disc[1]) < disc[2] - 1  # fully covered
        assert np.allclose(img[j, i], _by_hand(pin, disc, i, j, LIGHTS, p), atol=1e-9)


def test_specular_highlight_per_light_and_numpy_reference_agrees() -> None:
    p = Phong()
    img, pin, disc = _draw(LIGHTS, p)
    # the numpy Phong (used by nothing else) agrees with the kernel everywhere inside
    ys, xs = np.mgrid[0:H, 0:W]
    ux, uy = (xs + 0.5 - disc[0]) / disc[2], (disc[1] - (ys + 0.5)) / disc[2]
    inside = ux ** 2 + uy ** 2 < (1 - 1.5 / disc[2]) ** 2
    uz = np.sqrt(np.maximum(1 - ux ** 2 - uy ** 2, 0))[inside]
    n = ux[inside, None] * pin.right + uy[inside, None] * pin.up - uz[:, None] * pin.forward
    ref = phong(CENTRE + R * n, n, pin.observer, LIGHTS, ALBEDO, p)
    assert np.allclose(img[inside], ref, atol=1e-9)
    # two lights -> two separate highlights (thesis fig 6.9 "multiple highlights")
    matte = Phong(ks=0.0)

    def spec(lights: Lights) -> np.ndarray:
        return (_draw(lights, p)[0] - _draw(lights, matte)[0]).sum(axis=2)

    both = spec(LIGHTS)
    peaks = []
    for k in range(2):
        one = Lights(LIGHTS.positions[k:k + 1], LIGHTS.colours[k:k + 1], LIGHTS.ambient)
        peaks.append(np.unravel_index(np.argmax(spec(one)), both.shape))
    assert math.dist(peaks[0], peaks[1]) > 3
    assert all(both[pk] > 0.5 * both.max() for pk in peaks)
