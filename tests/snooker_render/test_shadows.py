"""Shadow ellipses against the light geometry (thesis 6.4.1: "one axis is the diameter of
the ball and the eccentricity and position are related to the direction from the ball to
the light source"), and the rendered shadow where the ellipse says."""

from __future__ import annotations

import math

import numpy as np
import pytest

from camlab88.apps.snooker.render.frame import frame_geometry
from camlab88.apps.snooker.render.lights import Lights
from camlab88.apps.snooker.render.painter import ShadowItem
from camlab88.apps.snooker.render.shadow_pass import shadow_occlusion
from camlab88.apps.snooker.render.shadows import ball_shadow_ellipses, cushion_shadow_polygons
from tests.snooker_render.helpers import one_ball_scene, overhead

R = 0.0262


@pytest.mark.claim(
    "§6.4.1: each light's shadow of a ball on the baize is an ellipse, one axis the ball's "
    "diameter, eccentricity and position from the direction to the light",
    measured="the ellipse's axes and centre against a hand calculation",
    verdict="agrees")
def test_ellipse_axes_and_centre_from_the_light_direction() -> None:
    ball = np.array([[0.2, 0.1, R]])
    light = np.array([[0.2 + 0.6, 0.1 + 0.8, 1.1]])  # 1 m away horizontally, along (0.6, 0.8)
    (cx, cy, ux, uy, a, b, li), = ball_shadow_ellipses(ball, R, light)
    drop = 1.1 - R
    sin_e = drop / math.hypot(1.0, drop)
    assert b == R  # across the light's direction: the ball's diameter
    assert math.isclose(a, R / sin_e, rel_tol=1e-12)  # along it: stretched by 1 / sin(elevation)
    assert np.allclose((ux, uy), (-0.6, -0.8))  # pointing away from the light
    t = R / drop  # the ray from the light through the centre meets the baize ...
    assert np.allclose((cx, cy), (0.2 - 0.6 * t, 0.1 - 0.8 * t))  # ... beyond the ball
    assert li == 0


def test_light_straight_above_gives_a_circle_under_the_ball() -> None:
    (cx, cy, _ux, _uy, a, b, _li), = ball_shadow_ellipses(
        np.array([[0.5, -0.3, R]]), R, np.array([[0.5, -0.3, 1.0]]))
    assert (cx, cy) == (0.5, -0.3) and a == b == R


def test_rendered_shadow_covers_the_ellipse_on_the_baize() -> None:
    light = Lights(np.array([[0.9, 0.5, 1.0]]), np.full((1, 3), 0.3), np.full(3, 0.2))
    scene = one_ball_scene(0.1, 0.0, light)
    view = overhead(1, focal=90.0)
    g = frame_geometry(scene, np.array(view.observer), np.array(view.viewpoint),
                       view.focal_mm, 1, 768, 512)
    item = next(i for i in g.items if isinstance(i, ShadowItem))
    box, x0, y0 = shadow_occlusion(g, item, 512, 768)
    occ = np.zeros((512, 768))
    occ[y0:y0 + box.shape[1], x0:x0 + box.shape[2]] = box[0, :, :, 0]
    (cx, cy, ux, uy, a, b, _), = item.ellipses
    ys, xs = np.mgrid[0:512, 0:768]
    ground, _hit = g.pin.ground(xs + 0.5, ys + 0.5)
    du = (ground[..., 0] - cx) * ux + (ground[..., 1] - cy) * uy
    dv = -(ground[..., 0] - cx) * uy + (ground[..., 1] - cy) * ux
    q = np.sqrt((du / a) ** 2 + (dv / b) ** 2)
    px_m = 3.2 / g.pin.focal_px  # metres per pixel on the baize, looking straight down
    margin = 1.0 * px_m / b
    assert np.all(occ[q < 1 - margin] == 1.0)
    assert np.all(occ[q > 1 + 2 * margin] == 0.0)
    edge = np.abs(q - 1) < 0.3 * margin  # centres within 0.3 pixel of the outline
    assert np.mean((occ[edge] > 0) & (occ[edge] < 1)) > 0.5  # anti-aliased at its edge
    assert np.isclose(occ.sum() * px_m * px_m, math.pi * a * b, rtol=0.02)  # the area


def _nose_shadow(light: np.ndarray, nose: np.ndarray) -> np.ndarray:
    """Where the ray from the light over a cushion's nose (height h) meets the cloth."""
    t = light[2] / (light[2] - nose[2])
    return light[:2] + (nose[:2] - light[:2]) * t


@pytest.mark.claim(
    "§6.4.1: the shadows of the cushions on the table calculated from the directions to the "
    "light sources",
    measured="for the canopy's four bulbs and lights placed round the table: exactly the "
             "cushions with the light beyond them cast a shadow, and each shadow is the strip "
             "from the cushion's foot to where rays from the light over its nose meet the "
             "cloth (ray-cast here independently), clipped to the playing area",
    verdict="agrees")
@pytest.mark.parametrize("light", [(2.5, 0.0, 1.0), (-2.3, 0.4, 1.2), (0.5, 1.4, 0.9),
                                   (-0.9, -0.4, 1.0), (0.9, 0.4, 1.0)])
def test_cushion_shadow_strips_are_where_rays_over_the_noses_land(light: tuple) -> None:
    from camlab88.apps.snooker.render.tablemodel import CUSHION_H_M

    hl, hw = 1.8, 0.9
    lp = np.array(light)
    polys = cushion_shadow_polygons(hl, hw, lp[None])
    beyond = {"top": lp[0] > hl, "baulk": lp[0] < -hl, "left": lp[1] > hw, "right": lp[1] < -hw}
    assert len(polys) == sum(beyond.values())  # one strip per cushion the light is beyond
    for _, poly in polys:
        xy = poly[:, :2]
        assert np.allclose(poly[:, 2], 0.0)
        assert np.all(np.abs(xy[:, 0]) <= hl + 1e-9) and np.all(np.abs(xy[:, 1]) <= hw + 1e-9)
        # which cushion: the side its points hug
        side = max(beyond, key=lambda k: beyond[k] and np.sum(np.isclose(
            {"top": xy[:, 0] - hl, "baulk": xy[:, 0] + hl, "left": xy[:, 1] - hw,
             "right": xy[:, 1] + hw}[k], 0.0)))
        axis, edge = {"top": (0, hl), "baulk": (0, -hl), "left": (1, hw), "right": (1, -hw)}[side]
        # the strip's inner edge: the nose's shadow, ray-cast from the light at both corners
        noses = []
        for k in (-1.0, 1.0):
            nose = np.zeros(3)
            nose[axis], nose[1 - axis], nose[2] = edge, k * (hw if axis == 0 else hl), CUSHION_H_M
            noses.append(_nose_shadow(lp, nose))
        depth = abs(noses[0][axis] - edge)
        got = np.max(np.abs(xy[:, axis] - edge))
        assert got == pytest.approx(min(depth, 2 * (hl if axis == 0 else hw)), abs=1e-9)
        for v in xy:  # every vertex on the foot, on the nose's shadow line, or on the border
            on_line = abs((noses[1] - noses[0])[0] * (v - noses[0])[1]
                          - (noses[1] - noses[0])[1] * (v - noses[0])[0]) < 1e-9
            assert (abs(v[axis] - edge) < 1e-9 or on_line
                    or abs(abs(v[1 - axis]) - (hw if axis == 0 else hl)) < 1e-9), (side, v)


def test_cushion_shadows_only_from_lights_beyond_the_cushion() -> None:
    hl, hw = 1.8, 0.9
    assert cushion_shadow_polygons(hl, hw, np.array([[0.0, 0.0, 1.0]])) == []
    polys = cushion_shadow_polygons(hl, hw, np.array([[2.5, 0.0, 1.0]]))  # beyond the top
    assert len(polys) == 1
    li, poly = polys[0]
    assert li == 0 and np.all(poly[:, 0] <= hl + 1e-12) and poly[:, 0].min() < hl
