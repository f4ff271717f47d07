"""The actors renderer: silhouettes where the profile projects, shadows on the floor,
hidden surfaces, determinism."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.actors.model import Actor, ActorSet, Material, Part
from camlab88.apps.actors.render import (
    Look,
    Placed,
    Shot,
    Stage,
    linear_colour,
    render_frame,
    render_linear,
)
from camlab88.apps.snooker.render.lights import Lights
from camlab88.apps.snooker.render.pinhole import Pinhole

PROFILE = ((0.2, 0.0), (0.42, 0.25), (0.3, 0.5), (0.12, 0.8), (0.33, 1.1), (0.05, 1.3))
MATTE_RED = Material(1.0, 0.9, 0.0, 1.0)


def _stage(parts: tuple[Part, ...], lights: Lights | None = None,
           floor: tuple[int, int, int, int] = (-3, -3, 4, 4)) -> Stage:
    actor = Actor(1, "vase", (255, 0, 0), MATTE_RED, parts)
    lights = lights or Lights(np.array([[0.5, -0.5, 12.0]]), np.full((1, 3), 0.8),
                              np.full(3, 0.3))
    return Stage(ActorSet("life", {1: actor}), floor, lights, (Placed(1, 0.0, 0.0),))


def _red(img: np.ndarray) -> np.ndarray:
    i = img.astype(int)
    return (i[..., 0] > i[..., 1] + 30) & (i[..., 0] > i[..., 2] + 30)


def _inside(poly: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Even-odd rule at points (x, y) for a closed polygon (k, 2)."""
    out = np.zeros(x.shape, bool)
    for (x0, y0), (x1, y1) in zip(poly, np.roll(poly, -1, axis=0)):
        cross = (y0 > y) != (y1 > y)
        with np.errstate(divide="ignore", invalid="ignore"):
            xi = x0 + (y - y0) * (x1 - x0) / (y1 - y0)
        out ^= cross & (x < xi)
    return out


@pytest.mark.parametrize("scale", [(1.0, 1.0, 1.0), (1.5, 1.5, 0.8)])
def test_a_lathe_silhouette_is_its_profile_projected(scale: tuple[float, float, float]) -> None:
    w = h = 200
    shot = Shot((0.5, -60.5, 0.65), (0.5, -0.5, 0.65), 1200.0)
    stage = _stage((Part("lathe", PROFILE, scale),))
    mask = _red(render_frame(stage, shot, Look(w, h, ss=1, shadows=False)))
    # the outline: the profile and its mirror image, each point at the axis +- r sideways
    sx, _sy, sz = scale
    right = [(0.5 + r * sx, -0.5, z * sz) for r, z in PROFILE]
    left = [(0.5 - r * sx, -0.5, z * sz) for r, z in PROFILE[::-1]]
    pin = Pinhole.of(np.array(shot.observer), np.array(shot.viewpoint), shot.focal_mm, w, h)
    xy, _d, _v = pin.project(np.array(right + left))
    jj, ii = np.mgrid[0:h, 0:w]
    want = _inside(xy, ii + 0.5, jj + 0.5)
    assert want.sum() > 2000  # a picture big enough to mean something
    wrong = mask ^ want
    # only pixels on the outline may differ (the 24-sided lathe is within 1 % of a circle)
    near_edge = np.zeros_like(want)
    for dj in (-1, 0, 1):
        for di in (-1, 0, 1):
            near_edge |= np.roll(np.roll(want, dj, 0), di, 1) != want
    assert not np.any(wrong & ~near_edge), np.argwhere(wrong & ~near_edge)[:5]
    assert wrong.sum() < 0.06 * want.sum()


def _floor_luma(stage: Stage, shadows: bool) -> np.ndarray:
    shot = Shot((0.5, -0.5001, 30.0), (0.5, -0.5, 0.0), 120.0)  # straight down
    lin = render_linear(stage, shot, Look(160, 160, ss=1, shadows=shadows))
    return lin.mean(axis=2)


def test_a_tall_box_casts_its_shadow_on_the_floor_away_from_the_light() -> None:
    light = Lights(np.array([[-3.5, -0.5, 6.0]]), np.full((1, 3), 0.9), np.full(3, 0.1))
    stage = _stage((Part("box", (), (0.4, 0.4, 2.0)),), light)
    lit, dark = _floor_luma(stage, False), _floor_luma(stage, True)
    shot = Shot((0.5, -0.5001, 30.0), (0.5, -0.5, 0.0), 120.0)
    pin = Pinhole.of(np.array(shot.observer), np.array(shot.viewpoint), shot.focal_mm, 160, 160)
    # the light at x = -3.5, 6 up; the box's top (z = 2) shadows the floor out to
    # x = 0.7 + 2 * 4.2 / 4 = 2.8 on the far side; the near side is lit
    (far, near, beyond), _d, _v = pin.project(np.array([[2.0, -0.5, 0.0], [-1.0, -0.5, 0.0],
                                                        [3.3, -0.5, 0.0]]))
    at = lambda p: (int(p[1]), int(p[0]))  # noqa: E731
    assert dark[at(far)] < 0.5 * lit[at(far)]  # in the shadow
    assert dark[at(near)] == pytest.approx(lit[at(near)])  # the light's side: no shadow
    assert dark[at(beyond)] == pytest.approx(lit[at(beyond)])  # past the shadow's tip
    assert np.count_nonzero(dark < lit - 1e-6) > 100


def test_a_nearer_actor_hides_a_farther_one_whatever_the_order_placed() -> None:
    near = Actor(1, "near", (255, 0, 0), MATTE_RED, (Part("box", (), (0.8, 0.8, 0.8)),))
    far = Actor(2, "far", (0, 0, 255), MATTE_RED, (Part("box", (), (0.8, 0.8, 0.8)),))
    lights = Lights(np.array([[0.5, -3.0, 10.0]]), np.full((1, 3), 0.8), np.full(3, 0.3))
    shot = Shot((0.5, -12.5, 0.4), (0.5, 0.0, 0.4), 200.0)
    pics = []
    for order in ((1, 2), (2, 1)):
        placed = tuple(Placed(s, 0.0, 0.0 if s == 1 else -3.0) for s in order)
        stage = Stage(ActorSet("x", {1: near, 2: far}), (-2, -5, 3, 3), lights, placed)
        pics.append(render_frame(stage, shot, Look(64, 64, ss=1, shadows=False)))
    assert np.array_equal(pics[0], pics[1])
    assert _red(pics[0])[32, 32]


def test_the_same_stage_renders_to_the_same_bytes() -> None:
    stage = _stage((Part("lathe", PROFILE), Part("sphere", (), (0.2, 0.2, 0.2), (0, 0, 1.3))))
    shot = Shot((4.0, -6.0, 3.0), (0.5, -0.5, 0.5), 35.0)
    a = render_frame(stage, shot, Look(120, 80))
    assert np.array_equal(a, render_frame(stage, shot, Look(120, 80)))


def test_every_part_kind_draws_something_where_it_stands() -> None:
    for part in (Part("box", (), (0.5, 0.5, 0.5)), Part("sphere", (), (0.45, 0.45, 0.45)),
                 Part("extrude", ((-0.3, -0.3), (0.3, -0.3), (0.0, 0.1), (0.3, 0.3),
                                  (-0.3, 0.3)), (1, 1, 0.5)),
                 Part("lathe", PROFILE)):
        img = render_frame(_stage((part,)), Shot((0.5, -8.5, 4.0), (0.5, -0.5, 0.3), 80.0),
                           Look(64, 64, ss=1))
        assert _red(img)[30:35, 30:35].all(), part.kind


@pytest.mark.parametrize(("light", "cos"), [
    ((0.5, -0.5, 4.5), 1.0),  # straight above the box's top, 4 cells up
    ((0.5, -0.5, 40.5), 1.0),  # ten times as far: no attenuation, the same
    ((3.5, -0.5, 3.5), 2 ** -0.5),  # 45 degrees off: N.L and R.V both cos 45
])
def test_a_surface_is_shaded_by_phongs_three_terms_from_point_lights(
        light: tuple[float, float, float], cos: float) -> None:
    """Thesis §6.4.1's model: I = ka A c_a + sum over lights (kd A N.L + ks (R.V)^n) I_l,
    L towards the light's point, no fall-off with distance."""
    ka, kd, ks, n = 0.5, 0.6, 0.3, 4.0
    actor = Actor(1, "slab", (200, 100, 50), Material(ka, kd, ks, n),
                  (Part("box", (), (0.6, 0.6, 0.5)),))
    intensity, ambient = np.array([0.7, 0.6, 0.5]), np.array([0.2, 0.25, 0.3])
    lights = Lights(np.array([light]), intensity[None, :], ambient)
    stage = Stage(ActorSet("x", {1: actor}), (-3, -3, 4, 4), lights, (Placed(1, 0.0, 0.0),))
    shot = Shot((0.5, -0.5001, 30.0), (0.5, -0.5, 0.0), 600.0)  # straight down on the top
    lin = render_linear(stage, shot, Look(64, 64, ss=1, shadows=False))
    albedo = linear_colour((200, 100, 50))
    want = ka * ambient * albedo + (kd * albedo * cos + ks * cos ** n) * intensity
    assert lin[32, 32] == pytest.approx(want, abs=2e-3)
