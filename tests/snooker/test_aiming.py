"""Aim to pot this ball / aim to set up next shot: the computed velocity, simulated on an
otherwise empty table, does what was asked."""

from __future__ import annotations

import math

import numpy as np
import pytest

from camlab88.apps.snooker.aiming import AimError, aim_next_shot, aim_to_pot, nearest_pocket
from camlab88.apps.snooker.events import EventKind
from camlab88.apps.snooker.physics import simulate_to_rest
from camlab88.apps.snooker.table import CUE, Table
from tests.snooker.helpers import state_with

T = Table()


def run(table: Table, start: tuple[float, float], velocity: tuple[float, float]):
    s = state_with(table, {CUE: start}, {CUE: velocity})
    return simulate_to_rest(table, s)


def test_aim_to_pot_points_at_the_pocket_and_keeps_speed() -> None:
    s = state_with(T, {CUE: (1.0, 0.7)}, {CUE: (0.0, 2.0)})
    pocket = nearest_pocket(T, 0.0, 0.0)
    assert T.pockets[pocket].name == "baulk-right"
    aim = aim_to_pot(T, s, CUE, pocket)
    assert math.hypot(*aim.velocity) == pytest.approx(2.0) and aim.warning is None
    assert aim.old_velocity == (0.0, 2.0)
    frames, events = run(T, (1.0, 0.7), aim.velocity)
    pots = [e for e, _ in events if e.kind == EventKind.POCKET]
    assert pots and T.pockets[pots[0].b].name == "baulk-right"


def test_aim_to_pot_warns_when_too_slow() -> None:
    s = state_with(T, {CUE: (2.0, 0.9)}, {CUE: (0.2, 0.0)})
    aim = aim_to_pot(T, s, CUE, nearest_pocket(T, T.length_m, T.width_m))
    assert aim.warning is not None and "too slow" in aim.warning
    frames, events = run(T, (2.0, 0.9), aim.velocity)
    assert not any(e.kind == EventKind.POCKET for e, _ in events)


@pytest.mark.parametrize(
    "cushions,target,restitution",
    [
        ((), (2.5, 1.2), 0.8),
        (("top",), (2.0, 0.5), 0.8),
        (("left", "baulk", "right"), (0.9, 1.2), 0.8),  # the thesis's safety example
        (("left", "top", "right"), (2.0, 1.0), 1.0),
        (("right", "left"), (2.5, 0.6), 1.3),
    ],
)
def test_aim_next_shot_stops_on_the_target(cushions, target, restitution) -> None:
    table = T.with_changes(cushion_restitution=restitution)
    start = (1.2, 0.8)
    s = state_with(table, {CUE: start})
    aim = aim_next_shot(table, s, CUE, target, 0.0, cushions)
    assert aim.path[0] == start and aim.path[-1] == target and len(aim.path) == len(cushions) + 2
    frames, events = run(table, start, aim.velocity)
    hit = [table.segments[e.b].side for e, _ in events if e.kind == EventKind.CUSHION]
    assert tuple(hit) == cushions
    assert np.hypot(*(frames[-1].pos[CUE] - np.array(target))) < 1e-6
    for (_e, st), point in zip([ev for ev in events if ev[0].kind == EventKind.CUSHION],
                              aim.path[1:-1], strict=True):
        assert np.hypot(*(st.pos[CUE] - np.array(point))) < 1e-9  # the dotted path is exact


def test_aim_next_shot_with_speed_at_target() -> None:
    start, target = (0.6, 0.5), (2.6, 1.3)
    s = state_with(T, {CUE: start})
    aim = aim_next_shot(T, s, CUE, target, 0.5)
    frames, _ = run(T, start, aim.velocity)
    # The speed held during the frame in which the ball passes the target point.
    want = math.dist(start, target)
    pts = [f.pos[CUE] for f in frames]
    acc = 0.0
    for k in range(len(pts) - 1):
        step = float(np.hypot(*(pts[k + 1] - pts[k])))
        if acc + step >= want:
            speed = step * T.frame_rate
            break
        acc += step
    assert 0.5 <= speed <= 0.5 * 1.1


def test_impossible_aims_say_why() -> None:
    s = state_with(T, {CUE: (1.0, 0.9)})
    with pytest.raises(AimError, match="not on the playing area"):
        aim_next_shot(T, s, CUE, (-1.0, 0.5))
    with pytest.raises(AimError, match="unknown cushion"):
        aim_next_shot(T, s, CUE, (2.0, 0.5), 0.0, ("bottom",))
    with pytest.raises(AimError):
        aim_next_shot(T, s, CUE, (1.2, 0.9), 0.0, ("top", "top"))
