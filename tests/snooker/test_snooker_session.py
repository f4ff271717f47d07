"""Sessions and the timeline: stepping by frame and by event, restarting from a frame
(later frames kept for recovery), determinism, saving and restoring."""

from __future__ import annotations

import json

import pytest

from camlab88.apps.snooker.events import EventKind
from camlab88.apps.snooker.layout import break_off_direction
from camlab88.apps.snooker.session import Session, SessionError
from camlab88.apps.snooker.table import CUE, Table
from camlab88.apps.snooker.timeline import Cursor

T = Table()


def broken() -> Session:
    s = Session.new_game(T)
    ux, uy = break_off_direction(T, s.balls)
    s.set_velocity(CUE, 5 * ux, 5 * uy)
    s.simulate_to_rest()
    return s


def test_two_stacks_and_frame_times() -> None:
    s = broken()
    tl = s.timeline
    for n, f in enumerate(tl.time_frames):
        assert f.index == n and f.balls.t == n / 25
    for f in tl.event_frames:
        assert tl.time_frames[f.index].balls.t <= f.balls.t
        if f.index + 1 < len(tl.time_frames):
            assert f.balls.t <= tl.time_frames[f.index + 1].balls.t
    kinds = [f.event.kind for f in tl.event_frames]
    assert kinds[0] == EventKind.INTERVENTION and kinds[-1] == EventKind.SHOT_END
    assert EventKind.BALL_BALL in kinds


def test_step_by_frame_and_by_event() -> None:
    s = broken()
    tl = s.timeline
    end = s.cursor
    assert end == tl.head
    s.step(-1, "frame")
    assert s.cursor != end
    s.step(+1, "frame")
    assert s.cursor == end
    seen = []
    s.goto_time_frame(0)
    while True:
        before = s.cursor
        s.step(+1, "event")
        if s.cursor == before:
            break
        seen.append(s.cursor)
        if s.cursor == tl.order()[-1]:
            break
    assert all(c.kind == "event" for c in seen) and len(seen) == len(tl.event_frames)
    s.step(-3, "event")
    assert s.cursor == Cursor("event", len(tl.event_frames) - 4)
    s.step(-1000, "frame")
    assert s.cursor == Cursor("time", 0)
    # The status shown follows the frame: before the first collision nothing has happened.
    assert s.status()["collision"] == 0 and s.status()["frame"] == 0


def test_restart_from_a_collision_frame_and_recover() -> None:
    s = broken()
    tl = s.timeline
    n_time, n_events, n_invalid = len(tl.time_frames), len(tl.event_frames), len(tl.invalid)
    first_hit = next(k for k, f in enumerate(tl.event_frames)
                     if f.event.kind == EventKind.BALL_BALL)
    s.cursor = Cursor("event", first_hit)
    hit_t = s.balls.t
    s.set_velocity(CUE, 0.0, 0.0)  # cheat at the collision: the cue ball stops dead
    assert len(tl.invalid) == n_invalid + 1
    assert len(tl.time_frames) == tl.event_frames[first_hit].index + 1
    assert s.frame.event.kind == EventKind.INTERVENTION and s.balls.t == hit_t
    assert s.balls.speed(CUE) == 0.0
    old_last = tl.invalid[-1].time_frames[-1]
    s.simulate_to_rest()
    assert not tl.time_frames[-1].balls.same_as(old_last.balls)
    assert s.recover()
    assert len(tl.time_frames) == n_time and len(tl.event_frames) == n_events


def test_same_edits_give_identical_frames() -> None:
    a, b = broken(), broken()
    assert len(a.timeline.time_frames) == len(b.timeline.time_frames)
    for x, y in zip(a.timeline.time_frames, b.timeline.time_frames, strict=True):
        assert x.balls.same_as(y.balls) and x.game == y.game


def test_save_restore_and_continue(tmp_path) -> None:
    s = broken()
    path = tmp_path / "game.json"
    s.save(path)
    r = Session.load(path)
    assert r.cursor == s.cursor and r.table == s.table
    for x, y in zip(s.timeline.time_frames, r.timeline.time_frames, strict=True):
        assert x.balls.same_as(y.balls) and x.game == y.game and x.shot == y.shot
    assert [f.event for f in r.timeline.event_frames] == [f.event for f in s.timeline.event_frames]
    for sess in (s, r):
        sess.strike(CUE, 2.0, 30.0, -0.2)
        sess.simulate_to_rest()
    assert s.timeline.time_frames[-1].balls.same_as(r.timeline.time_frames[-1].balls)
    assert s.status() == r.status()


def test_bad_session_files(tmp_path) -> None:
    p = tmp_path / "s.json"
    p.write_text('{"format": "camlab88-snooker-session",\n "version": 1, oops}')
    with pytest.raises(SessionError, match=r"s.json:2:"):
        Session.load(p)
    p.write_text(json.dumps({"format": "something-else"}))
    with pytest.raises(SessionError, match="not a snooker session"):
        Session.load(p)
    good = Session.new_game(T).to_json()
    good["time_frames"][0]["balls"]["pos"] = [[0, 0]] * 3
    p.write_text(json.dumps(good))
    with pytest.raises(SessionError, match=r"time_frames\[0\]"):
        Session.load(p)
    good = Session.new_game(T).to_json()
    good["table"]["cushion_restitution"] = -1
    p.write_text(json.dumps(good))
    with pytest.raises(SessionError, match="cushion_restitution"):
        Session.load(p)


def test_positions_off_the_table_are_potted() -> None:
    s = Session.new_game(T)
    s.set_position(6, -0.2, 0.5)
    assert not s.balls.on_table[6]
    assert s.select_ball_at(*T.spots[5]) == 5 and s.select_ball_at(0.05, 0.05) is None


def test_speeds_over_the_table_limit_are_refused() -> None:
    s = Session.new_game(T)
    with pytest.raises(SessionError, match="max_speed_m_s"):
        s.set_velocity(CUE, 40.0, 0.0)
    from camlab88.apps.snooker.aiming import AimError

    slow = Session.new_game(T.with_changes(max_speed_m_s=0.5))
    with pytest.raises(AimError, match="max_speed_m_s"):
        slow.aim_next_shot(CUE, (3.0, 1.5), 0.0, ("left", "top"))


def test_frame_by_frame_equals_all_at_once() -> None:
    """The interactive program simulates one frame per display tick: same frames."""
    a = Session.new_game(T)
    b = Session.new_game(T)
    for s in (a, b):
        ux, uy = break_off_direction(T, s.balls)
        s.set_velocity(CUE, 6 * ux, 6 * uy, 0.4)
    a.simulate_to_rest()
    for _ in range(100000):
        added = b.simulate_frame()
        if not added or added[-1].event is not None \
                and added[-1].event.kind == EventKind.SHOT_END:
            break
    assert len(a.timeline.time_frames) == len(b.timeline.time_frames)
    for x, y in zip(a.timeline.time_frames, b.timeline.time_frames, strict=True):
        assert x.balls.same_as(y.balls) and x.game == y.game
    assert [f.event for f in a.timeline.event_frames] == [f.event for f in b.timeline.event_frames]
