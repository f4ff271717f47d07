"""Events from positions: moved / starts / stops, and the cue ball's strikes inferred from a
checkpoint (compared with a session's collision events on real shots)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from camlab88.apps.snooker.camera import motion
from camlab88.apps.snooker.camera.motion import infer_strikes, timeline_events
from camlab88.apps.snooker.session import Session
from camlab88.apps.snooker.table import CUE, Table
from tests.snooker_camera.helpers import R, make, still

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker_camera"


def test_the_shipped_shot_strike_agrees_with_its_session() -> None:
    a = motion.load(DATA / "pink_shot.checkpoint")
    b = motion.load(DATA / "pink_shot.session.json")
    assert a.strikes == b.strikes == ((44, 5),)
    assert np.array_equal(a.centres, b.centres) and np.array_equal(a.on_table, b.on_table)


@pytest.mark.parametrize(("speed", "angle"), [(2.0, 10.0), (4.0, 3.0), (3.0, 12.0),
                                            (5.0, 8.0)])
def test_inferred_strikes_match_the_session_on_simulated_shots(speed, angle) -> None:
    s = Session.new_game(Table())
    s.strike(CUE, speed, angle)
    s.simulate_to_rest()
    from_events = motion.from_session(s).strikes
    assert from_events, "the shot hits something"
    assert motion.from_checkpoint(s.checkpoint(), s.table).strikes == from_events


def test_into_the_pack_the_first_strike_is_found() -> None:
    s = Session.new_game(Table())
    s.strike(CUE, 7.0, 2.0)
    s.simulate_to_rest()
    from_events = motion.from_session(s).strikes
    inferred = motion.from_checkpoint(s.checkpoint(), s.table).strikes
    assert inferred[0] == from_events[0] == (9, 8)


def test_no_strike_for_a_near_miss_or_balls_touching_at_rest() -> None:
    c = still(6)
    for f in range(6):  # the cue ball passes 3 cm clear of the yellow ...
        c[f, CUE] = (-0.1 + 0.04 * f, -(2 * R + 0.03), R)
    c[:, 1] = (0.0, 0.0, R)
    c[3:, 1, 1] += 0.03 * np.arange(1, 4)  # ... just as something else sets it moving
    c[:, 2] = c[:, 3] + (2 * R, 0, 0)  # green touching brown, both at rest
    assert infer_strikes(c, np.ones(c.shape[:2], bool), R) == ()


def test_a_resting_ball_pushed_by_the_cue_ball_is_a_strike() -> None:
    c = still(6)
    c[:, 1] = (0.0, 0.0, R)
    for f in range(6):
        c[f, CUE] = (-0.2 + 0.06 * min(f, 3) - 2 * R * (f > 3), 0.0, R)
    c[4:, CUE, 0] = -2 * R  # it stops on contact at frame 5 ...
    c[4, 1, 0], c[5, 1, 0] = 0.03, 0.09  # ... and the yellow moves off
    assert infer_strikes(c, np.ones(c.shape[:2], bool), R) == ((5, 1),)


def test_starts_stops_and_the_timeline() -> None:
    c = still(10)
    for f in (3, 4, 5, 8):  # the pink moves into frames 3-5, then again into 8
        c[f - 1:, 5, 0] += 0.05
    ev = timeline_events(make(c, ((3, 5),)))
    assert ev == [(3, "start", 5), (3, "strike", 5), (5, "stop", 5), (8, "start", 5),
                  (8, "stop", 5)]
