"""The program's behaviours on the emulated Rainbow, one at a time (scripted input)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from camlab88.apps.snooker import checkpoint
from camlab88.apps.snooker.program import menus, pads
from camlab88.apps.snooker.program.program import MAGNIFY, WARN_COLOUR, Program
from camlab88.apps.snooker.session import Session
from camlab88.apps.snooker.table import BLUE, CUE
from tests.snooker_program.helpers import EMPTY, feed, hex_rgb, saved_game, screen_colour

CUE_AT = (175, 325)  # the cue ball's pixel in the opening position
def test_pads_transparency_and_cursor(rainbow, prog):
    d = prog.display
    assert screen_colour(rainbow, *CUE_AT) == hex_rgb(pads.BALL_COLOURS[1])
    assert screen_colour(rainbow, 300, 200) == hex_rgb(pads.TABLE_COLOURS[pads.CLOTH])
    assert screen_colour(rainbow, *EMPTY) == hex_rgb(pads.CURSOR_COLOUR)
    bx, by = prog.view.to_pixel(*prog.session.table.spots[BLUE])
    assert screen_colour(rainbow, bx, by) == hex_rgb(pads.BALL_COLOURS[5])
    # the table sits in one pad; the balls in two pads, only one shown at a time
    assert len({d.table_pad, *d.balls.pads, d.cursor_pad}) == 4
    swaps = d.balls.swaps
    feed(rainbow, prog, "move 310 420\nwait 1")  # nothing changed: no redraw, no swap
    assert d.balls.swaps == swaps
    shown = d.balls.front
    feed(rainbow, prog, f"move {CUE_AT[0]} {CUE_AT[1]}\nwait 1")  # the ring: a redraw
    assert d.balls.swaps == swaps + 1 and d.balls.front != shown


def test_green_menu_right_of_cursor_with_do_nothing_first(rainbow, prog):
    feed(rainbow, prog, "press middle\nwait 1")
    m = prog.menu
    assert m is prog.green and m.highlighted == menus.GREEN_ITEMS.index(menus.DO_NOTHING)
    assert m.x > EMPTY[0]
    feed(rainbow, prog, "release middle\nwait 1")
    assert prog.mode == "idle" and prog.menu is None


def test_orange_menu_on_a_ball_and_the_message_colour(rainbow, prog):
    feed(rainbow, prog, f"move {CUE_AT[0]} {CUE_AT[1]}\npress middle\nwait 1")
    assert prog.menu is prog.orange
    assert prog.menu.highlighted == menus.ORANGE_ITEMS.index(menus.DO_NOTHING)
    # up three items: "Stop all balls moving"
    feed(rainbow, prog, f"glide {CUE_AT[0]} {CUE_AT[1] - 60} 20\nwait 1\nrelease middle\nwait 1")
    assert prog.help_colour == menus.HIGHLIGHT[menus.STOP_ALL]
    assert screen_colour(rainbow, 200, 30) == hex_rgb(menus.HIGHLIGHT[menus.STOP_ALL])


def test_left_button_magnifies_movement(rainbow, prog):
    feed(rainbow, prog, "press left\nmove 310 420\nrelease left\nmove 320 420\nwait 1")
    assert prog.cursor == (EMPTY[0] + 10 * MAGNIFY + 10, EMPTY[1])


def test_keyboard_velocity_and_right_button_restarts(rainbow, prog):
    s = prog.session
    prog.ball = CUE
    prog.ask("velocity", "v?")
    feed(rainbow, prog, "type 2 90\nkey return\nwait 1")
    assert s.balls.vel[CUE] == pytest.approx((0.0, 2.0), abs=1e-12)
    feed(rainbow, prog, "press right\nrelease right\nwait 20")
    assert prog.mode == "running" and s.frame_number == 10  # 25 frames/s on a 50 Hz display
    feed(rainbow, prog, "press middle\nwait 1\nrelease middle\nwait 4")
    assert prog.mode == "idle" and s.frame_number == 10  # interrupted


def test_keyboard_position_and_bad_input(rainbow, prog):
    prog.ball = BLUE
    prog.ask("position", "where?")
    feed(rainbow, prog, "type 1.5,x\nkey return\nwait 1")
    assert prog.help_colour == WARN_COLOUR and prog.mode == "keys:position"
    feed(rainbow, prog, "type 1.5, 0.5\nkey return\nwait 1")
    assert tuple(prog.session.balls.pos[BLUE]) == (1.5, 0.5)


def test_mouse_position_change(rainbow, prog):
    prog.ball = BLUE
    prog.mode = "position"
    feed(rainbow, prog, "move 500 400\npress middle\nglide 520 410 4\nrelease middle\nwait 1")
    assert prog.session.balls.pos[BLUE] == pytest.approx(prog.view.to_table(520, 410))


def test_aim_to_pot_keeps_speed_and_warns(rainbow, prog):
    s = prog.session
    s.strike(BLUE, 0.3, 0.0)
    prog.ball = BLUE
    prog.mode = "aim_pot"
    x, y, w, h = prog.view.play_rect
    feed(rainbow, prog, f"move {x + w} {y}\npress middle\nrelease middle\nwait 1")
    vx, vy = s.balls.vel[BLUE]
    assert math.hypot(vx, vy) == pytest.approx(0.3)
    pocket = s.table.pockets[s.table.pocket_index("top-left")].centre
    bx, by = s.balls.pos[BLUE]
    assert math.atan2(vy, vx) == pytest.approx(math.atan2(pocket[1] - by, pocket[0] - bx),
                                               abs=0.02)
    assert "WARNING" in prog.help_text and prog.help_colour == WARN_COLOUR


def test_stop_all_and_replay(rainbow, prog):
    s = prog.session
    s.strike(CUE, 1.0, 90.0)
    feed(rainbow, prog, "press right\nrelease right\nwait 24")
    assert s.frame_number == 12
    s.stop_all()
    assert not s.balls.any_moving()
    prog.ask("replay", "?")
    feed(rainbow, prog, "type 3 6\nkey return\nwait 1")
    assert prog.mode == "replay" and prog.replay == [3, 4, 5, 6]
    shown = []
    for _ in range(8):
        prog.step()
        shown.append(prog.replay[prog.replay_at] if prog.mode == "replay" else None)
    assert shown[:6] == [4, 4, 5, 5, 6, 6] and prog.mode == "idle"  # 2 display frames each


def test_alter_frame_auto_repeat_and_units(rainbow, prog):
    s = prog.session
    s.strike(CUE, 3.0, 0.0)
    s.simulate_to_rest()
    s.goto_time_frame(0)
    prog.mode = "alter"
    feed(rainbow, prog, "press right\nwait 1")
    assert s.frame_number == 0 and s.cursor.kind == "event"  # the intervention at frame 0
    feed(rainbow, prog, "wait 20\nrelease right\nwait 1")
    forward = s.frame_number
    assert forward >= 4  # auto-repeat
    feed(rainbow, prog, "glide 300 450 4\npress right\nrelease right\nwait 1")
    assert prog.unit == "event" and s.cursor.kind == "event"
    feed(rainbow, prog, "glide 300 400 4\nwait 1")
    assert prog.unit == "frame"
    st = s.status()
    assert st["frame"] == s.frame_number and prog.display.frame_box.shown[0].startswith(
        f"frame {s.frame_number}")


def test_start_new_or_restore_and_exit_saves(rainbow, tmp_path):
    path = tmp_path / "game.json"
    saved = saved_game(path, 45.0)
    p = Program(rainbow.client, restore=Session.load(path), save_to=path)
    feed(rainbow, p, "key x\nwait 1")
    assert p.mode == "start"
    feed(rainbow, p, "key r\nwait 1")
    assert p.mode == "idle"
    assert np.array_equal(p.session.balls.pos, saved.balls.pos)
    # the saved session itself, with its frames (a new game has one)
    assert len(p.session.timeline.time_frames) == len(saved.timeline.time_frames) > 1
    p.session.strike(CUE, 0.5, 0.0)
    p.mode = "exit"
    feed(rainbow, p, "key y\nwait 1\nkey return\nwait 1")  # Return: all the frames
    assert p.done and (tmp_path / "game.cp").exists()
    again = Session.load(path)
    assert again.balls.vel[CUE] == pytest.approx((0.5, 0.0))


def test_a_refused_change_is_reported_not_fatal(rainbow, prog):
    s = prog.session
    s.set_position(BLUE, -1.0, -1.0)  # potted: off the table
    prog.ball = BLUE
    prog.mode = "aim_target"
    feed(rainbow, prog, "move 400 200\npress middle\nrelease middle\nwait 1\nkey return\n"
         "wait 1\nkey return\nwait 1")
    assert prog.mode == "idle" and prog.help_colour == WARN_COLOUR
    prog.ball = BLUE
    prog.mode = "position"
    feed(rainbow, prog, "press middle\nmove 410 200\nrelease middle\nwait 1")
    assert s.balls.on_table[BLUE]  # a potted ball can be put back by the mouse
    s.strike(BLUE, 0.5, 0.0)
    prog.ball = BLUE
    prog.ask("velocity", "?")
    feed(rainbow, prog, "type 99 0\nkey return\nwait 1")  # faster than the table allows
    assert prog.help_colour == WARN_COLOUR and "max_speed" in prog.help_text
    assert prog.session.balls.vel[BLUE] == pytest.approx((0.5, 0.0))


def test_exit_without_a_file_asks_for_one_and_a_frame_range(rainbow, tmp_path, monkeypatch):
    # §6.2.2: on leaving, save "either the complete sequence or a subset of frames"
    monkeypatch.chdir(tmp_path)
    p = Program(rainbow.client)  # no SESSION, no --save
    p.session.strike(CUE, 1.0, 10.0)
    for _ in range(8):
        p.session.simulate_frame()
    n = len(p.session.timeline.time_frames)
    assert n > 6
    p.mode = "exit"
    feed(rainbow, p, "key y\nwait 1")
    assert not p.done and p.mode == "keys:exit_file"
    feed(rainbow, p, "key return\nwait 1")  # an empty name is refused, asked again
    assert not p.done and p.mode == "keys:exit_file" and p.help_colour == WARN_COLOUR
    feed(rainbow, p, "type shot.json\nkey return\nwait 1")
    assert not p.done and p.mode == "keys:exit_range" and f"0..{n - 1}" in p.help_text
    feed(rainbow, p, f"type 2 {n + 5}\nkey return\nwait 1")  # out of range: asked again
    assert not p.done and p.mode == "keys:exit_range" and p.help_colour == WARN_COLOUR
    feed(rainbow, p, "type 2 5\nkey return\nwait 1")
    assert p.done
    assert [q.resolve() for q in p.saved] == [tmp_path / "shot.json", tmp_path / "shot.cp"]
    cp = checkpoint.read(tmp_path / "shot.cp")
    assert cp.n_frames == 4
    assert np.array_equal(cp.positions, p.session.checkpoint(2, 5).positions)
    assert Session.load(tmp_path / "shot.json").frame_number == p.session.frame_number


def test_exit_with_a_known_file_saves_all_frames_by_default(rainbow, tmp_path):
    p = Program(rainbow.client, save_to=tmp_path / "game.json")
    p.session.strike(CUE, 1.0, 10.0)
    for _ in range(5):
        p.session.simulate_frame()
    p.mode = "exit"
    feed(rainbow, p, "key y\nwait 1")
    assert p.mode == "keys:exit_range"  # the file is known: only the range is asked
    feed(rainbow, p, "key return\nwait 1")
    assert p.done
    cp = checkpoint.read(tmp_path / "game.cp")
    assert np.array_equal(cp.positions, p.session.checkpoint().positions)


def test_exit_to_an_unwritable_place_is_reported_not_fatal(rainbow, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    p = Program(rainbow.client)
    p.mode = "exit"
    feed(rainbow, p, "key y\nwait 1\ntype nodir/x.json\nkey return\nwait 1\nkey return\nwait 1")
    assert not p.done and p.mode == "idle" and p.help_colour == WARN_COLOUR
    assert "nodir" in p.help_text and p.save_to is None


def test_exit_to_a_cp_name_keeps_session_and_checkpoint_apart(rainbow, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    p = Program(rainbow.client)
    p.mode = "exit"
    feed(rainbow, p, "key y\nwait 1\ntype run.cp\nkey return\nwait 1\nkey return\nwait 1")
    assert p.done
    assert Session.load(tmp_path / "run.json").frame_number == 0
    assert checkpoint.read(tmp_path / "run.cp").n_frames == 1
