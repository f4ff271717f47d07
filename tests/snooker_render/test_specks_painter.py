"""Dust specks turn as the ball rolls; the painter's order is the thesis's."""

from __future__ import annotations

import math

import numpy as np
import pytest

from camlab88.apps.snooker.render.painter import BallItem, PolygonItem, ShadowItem, plan
from camlab88.apps.snooker.render.specks import orientations, rolling_rotations
from tests.snooker_render.helpers import break_scene

R = 0.0262


@pytest.mark.claim(
    "§6.5: specks of dust on the balls suggest that balls are rolling rather than sliding",
    measured="a ball rolling forward turns its specks the way it rolls",
    verdict="agrees")
def test_rolling_forward_turns_the_top_forward() -> None:
    rot = rolling_rotations(np.array([[0.01, 0.0]]), R)[0]
    top = rot @ np.array([0.0, 0.0, 1.0])
    assert top[0] > 0 and abs(top[1]) < 1e-12  # the top moves the way the ball goes
    assert np.isclose(math.acos(top[2]), 0.01 / R)  # turned by distance / radius


def test_a_full_circumference_brings_the_ball_back() -> None:
    n = 50
    step = 2 * math.pi * R / n
    centres = np.zeros((n + 1, 1, 3))
    centres[:, 0, 0] = np.arange(n + 1) * step * 0.6
    centres[:, 0, 1] = np.arange(n + 1) * step * 0.8
    m = orientations(centres, np.ones((n + 1, 1), dtype=bool), R)
    assert np.allclose(m[-1, 0], np.eye(3), atol=1e-9)
    assert not np.allclose(m[n // 2, 0], np.eye(3))


def test_balls_at_rest_keep_their_specks_and_moving_balls_turn() -> None:
    s = break_scene()
    m = s.orientations
    moved = np.linalg.norm(s.centres[-1] - s.centres[0], axis=1) > 1e-6
    assert moved.any() and (~moved).any()
    assert np.allclose(m[-1][~moved], np.eye(3))
    assert not np.allclose(m[-1][moved], np.eye(3))


def _kinds(items: list) -> list[str]:
    out = []
    for it in items:
        if isinstance(it, BallItem):
            out.append("ball")
        elif isinstance(it, ShadowItem):
            out.append("shadows")
        elif isinstance(it, PolygonItem):
            f = it.face
            out.append(f.group if not f.side else f"{f.group}:{f.side}")
    return out


def test_painters_order_from_above_puts_every_cushion_behind_the_balls() -> None:
    s = break_scene()
    eye = np.array([0.0, 0.0, 2.0])
    k = _kinds(plan(s, 0, eye, np.zeros(22)))
    first_ball = k.index("ball")
    assert k.index("surface") < k.index("shadows") < first_ball
    assert all(not x.startswith(("cushion", "rail")) for x in k[first_ball:])
    assert k[0] == "leg"  # legs first, whatever the table will hide of them


@pytest.mark.claim(
    "§6.4.1: hidden surfaces by the painter's algorithm: legs, playing surface and shadows, far "
    "cushions, balls back to front, near cushions last",
    measured="the drawing order from behind baulk",
    verdict="agrees")
def test_painters_order_from_behind_baulk_draws_the_baulk_side_last() -> None:
    s = break_scene()
    eye = np.array([-2.6, 0.0, 0.6])  # beyond the baulk cushion, low
    depth = np.linalg.norm(s.centres[0] - eye, axis=1)
    items = plan(s, 0, eye, depth)
    k = _kinds(items)
    last_ball = len(k) - 1 - k[::-1].index("ball")
    assert set(k[last_ball + 1:]) == {"cushion:baulk", "rail:baulk"}
    assert k.index("leg") < k.index("surface")  # legs first of all
    balls = [it for it in items if isinstance(it, BallItem)]
    d = [depth[b.ball] for b in balls]
    assert d == sorted(d, reverse=True)  # back to front



def _ball_close_up(side_deg: float, specks: bool, x: float = 0.3) -> np.ndarray:
    """The cue ball at (x, 0.1) seen from 28 cm away, from `side_deg` round it."""
    from camlab88.apps.snooker.camera.views import View
    from camlab88.apps.snooker.render.truecolour import RenderOptions, render_frame
    from tests.snooker_render.helpers import one_ball_scene

    s = one_ball_scene(x, 0.1)
    a = math.radians(side_deg)
    eye = (x - 0.25 * math.cos(a), 0.1 - 0.25 * math.sin(a), 0.16)
    view = View(1, eye, (x, 0.1, s.table.radius), 50.0)
    return render_frame(s, view, RenderOptions(specks=specks, shadows=False))


@pytest.mark.claim(
    "§6.4.1/§6.5: a rudimentary, subtle representation of specks of dust on the balls",
    measured="a close-up of the cue ball (about 180 px across) from three sides, rendered with "
             "and without specks: the pixels the specks change are at most 1 % of the ball's "
             "disc (0.2 %), and none differs by more than a tenth of the ball's own shading "
             "range (luminance, highlight to shade)",
    verdict="agrees (how many specks, their size and tint are ours: docs/fidelity/snooker.md)")
@pytest.mark.parametrize("side", [0.0, 120.0, 240.0])
def test_specks_are_small_few_and_low_contrast(side: float) -> None:
    plain = _ball_close_up(side, specks=False).astype(np.int64)
    dusty = _ball_close_up(side, specks=True).astype(np.int64)
    cloth = _ball_close_up(side, specks=False, x=0.8).astype(np.int64)  # the ball moved away
    ball = np.any(plain != cloth, axis=2)  # the ball's own pixels (and its blended edge)
    area = ball.sum()
    assert area > 20000  # a close-up: the ball about 180 px across
    diff = np.abs(dusty - plain).max(axis=2)
    speck = diff > 0
    assert speck.any()  # there are specks to see
    assert speck.sum() <= 0.01 * area, (speck.sum(), area)
    lum = plain[ball] @ np.array([0.299, 0.587, 0.114])
    shading_range = lum.max() - lum.min()
    assert diff.max() <= 0.1 * shading_range, (diff.max(), shading_range)
