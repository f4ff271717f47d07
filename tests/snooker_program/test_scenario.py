"""The §6.2.2 working style driven by scripted mouse events (tests/data/snooker_program/
scenario.events): select the cue ball, the scrolling orange menu, the velocity arrow, start,
interrupt, alter a different frame, aim to set up next shot, accept, restart. Checks the
model at each stage and the Rainbow's frame against golden images."""

from __future__ import annotations

import math

import numpy as np
import pytest

from camlab88.apps.snooker.program import menus, script_events
from camlab88.apps.snooker.program.program import Program
from camlab88.apps.snooker.table import CUE
from tests.snooker_program.conftest import DATA
from tests.support.golden import assert_matches_golden


@pytest.fixture(scope="module")
def run():
    from camlab88.emulator.machine import RainbowMachine

    rb = RainbowMachine()
    program = Program(rb.client)
    player = script_events.Player(script_events.load(DATA / "scenario.events"))
    trace: list[dict] = []
    frames: dict[str, np.ndarray] = {}
    while not player.finished:
        for e in player.due():
            rb.post(e)
        program.step()
        s = program.session
        trace.append({"mode": program.mode, "cursor": s.cursor, "frame": s.frame_number,
                      "menu": program.menu.items[program.menu.highlighted]
                      if program.menu is not None and program.menu.highlighted is not None
                      else None, "help": program.help_colour, "unit": program.unit,
                      "cue_vel": tuple(s.balls.vel[CUE]), "status": s.status()})
        mode = program.mode
        if mode not in frames:
            frames[mode] = rb.executor.last_frame.copy()
        if mode == "menu" and trace[-1]["menu"] == menus.VELOCITY_MOUSE:
            frames["orange_scrolled"] = rb.executor.last_frame.copy()
    frames["end"] = rb.executor.last_frame.copy()
    return program, trace, frames


def modes(trace):
    out = []
    for t in trace:
        if not out or out[-1] != t["mode"]:
            out.append(t["mode"])
    return out


def test_the_sequence_of_modes(run):
    _, trace, _ = run
    assert modes(trace) == [
        "idle", "menu", "velocity", "spin", "running", "menu", "alter", "idle", "menu",
        "aim_target", "keys:aim_speed", "keys:aim_cushions", "aim_confirm", "idle",
        "running", "idle"]


def test_menu_choices(run):
    _, trace, _ = run
    chosen = [a["menu"] for a, t in zip(trace, trace[1:]) if a["mode"] == "menu"
              and t["mode"] != "menu"]
    assert chosen == [menus.VELOCITY_MOUSE, menus.ALTER_FRAME, menus.AIM_NEXT]


def test_velocity_arrow_sets_the_cue_ball_moving(run):
    program, trace, _ = run
    first_run = next(t for t in trace if t["mode"] == "running")
    vx, vy = first_run["cue_vel"]
    # the arrow ran from the cue ball (175, 325) to (440, 300): up the table, a little left
    assert vx > 5.0 and 0 < vy < 1.0
    assert math.isclose(math.atan2(vy, vx), math.atan2(25 / 1, 265 / 1) * 1, rel_tol=0.05)


def test_alter_a_different_frame_steps_back_to_the_first_frame(run):
    _, trace, _ = run
    alter = [t for t in trace if t["mode"] == "alter"]
    frames = [t["frame"] for t in alter]
    assert frames[0] > 40 and frames[-1] == 0
    assert all(b <= a for a, b in zip(frames, frames[1:]))  # only ever backwards
    assert {t["unit"] for t in alter} == {"frame", "event"}  # the mouse switched units
    # score, frame and collision number are those of the frame shown
    assert alter[-1]["status"]["collision"] == 0 and alter[-1]["status"]["frame"] == 0


def test_aim_to_set_up_next_shot_brings_the_cue_ball_to_the_target(run):
    program, trace, _ = run
    s = program.session
    target = program.view.to_table(400, 160)
    assert not s.balls.any_moving()
    assert math.dist(s.balls.pos[CUE], target) < 1e-6
    # off the left cushion (the top of the screen): one cushion collision, nothing else
    assert s.status()["collision"] == 1
    confirm = next(t for t in trace if t["mode"] == "aim_confirm")
    assert confirm["help"] == menus.HIGHLIGHT[menus.AIM_NEXT]
    # the first frames of the old attempt were made invalid (recoverable), not lost
    assert s.timeline.invalid


def test_golden_frames(run):
    _, _, frames = run
    for name in ("orange_scrolled", "spin", "alter", "aim_confirm", "end"):
        assert_matches_golden(frames[name], DATA / "golden" / f"scenario_{name}.png")
