"""Table constants altered from inside the program (§6.2, §6.5): key t opens the
table-constants pop-up; ball size and a cushion restitution above 1 are typed in, a shot is
played with them, and the saved session holds them."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.snooker.events import EventKind
from camlab88.apps.snooker.program import constants
from camlab88.apps.snooker.program.program import Program
from camlab88.apps.snooker.session import Session, SessionError
from camlab88.apps.snooker.table import CUE, Table
from tests.snooker_program.conftest import DATA
from tests.snooker_program.helpers import feed, hex_rgb, screen_colour
from tests.support.golden import assert_matches_golden

ROW = 18  # a menu row, pixels
# key t at (300, 200), off any ball: 'Do nothing' (the last item) under the cursor
BALL_SIZE = f"move 300 200\nwait 1\nkey t\nwait 1\nglide 300 {200 - 4 * ROW} 8\nwait 1\n" \
    "click middle\nwait 1\ntype 0.04\nkey return\nwait 1\n"
RESTITUTION = f"move 300 200\nwait 1\nkey t\nwait 1\nglide 300 {200 - 3 * ROW} 6\nwait 2\n"
CHOOSE_RESTITUTION = "click middle\nwait 1\ntype 1.2\nkey return\nwait 1\n"
# the cue ball's velocity by keyboard (orange menu, up from 'Do nothing'): 2 m/s towards
# the baulk cushion, then run until everything is at rest
SHOT = "move 175 325\nwait 1\npress middle\nglide 175 250 25\nwait 1\nrelease middle\n" \
    "wait 1\ntype 2 180\nkey return\nwait 1\npress right\nrelease right\nwait 900\n"
EXIT = "move 300 430\nwait 1\npress middle\nglide 300 412 6\nwait 1\nrelease middle\n" \
    "wait 1\nkey y\nwait 1\nkey return\nwait 1\n"


@pytest.fixture(scope="module")
def played(tmp_path_factory):
    from camlab88.emulator.machine import RainbowMachine

    rb = RainbowMachine()
    save = tmp_path_factory.mktemp("tc") / "game.json"
    program = Program(rb.client, save_to=save)
    feed(rb, program, BALL_SIZE + RESTITUTION)
    popup = rb.executor.last_frame.copy()
    highlighted = program.menu.items[program.menu.highlighted]
    feed(rb, program, CHOOSE_RESTITUTION)
    table = program.session.table
    feed(rb, program, SHOT)
    session = program.session
    feed(rb, program, EXIT)
    return program, session, table, popup, highlighted, save


def test_the_popup_is_the_pastel_table_menu(played):
    program, _, _, popup, highlighted, _ = played
    assert highlighted == constants.RESTITUTION
    m = program.constants
    row = m.y + constants.ITEMS.index(constants.RESTITUTION) * ROW + ROW // 2
    assert tuple(popup[row, m.x + 4]) == hex_rgb(constants.HIGHLIGHT[constants.RESTITUTION])
    assert tuple(popup[m.y + ROW // 2, m.x + 4]) == hex_rgb(constants.COLOUR)
    assert_matches_golden(popup, DATA / "golden" / "table_constants_popup.png")


def test_the_typed_constants_are_in_force(played):
    _, _, table, _, _, _ = played
    assert table.ball_diameter_m == 0.04
    assert table.cushion_restitution == 1.2
    assert table.deceleration_m_s2 == Table().deceleration_m_s2  # untouched


def test_the_shot_used_them(played):
    _, session, _, _, _, _ = played
    tl = session.timeline
    assert tl.physics.table.cushion_restitution == 1.2
    hits = [f for f in tl.event_frames if f.event is not None
            and f.event.kind == EventKind.CUSHION and CUE in (f.event.a, f.event.b)]
    assert hits, "the cue ball never reached the baulk cushion"
    vx = np.array([f.balls.vel[CUE, 0] for f in tl.time_frames])
    x = np.array([f.balls.pos[CUE, 0] for f in tl.time_frames])
    k = int(np.argmax(vx > 0))  # the first time frame after the bounce
    assert vx[k - 1] < 0 < vx[k]
    assert vx[k] > -vx[k - 1] * 1.1  # the cushion sent it back faster than it came in
    # the ball's edge, not its centre, met the cushion: the centre stops 0.02 m short
    assert 0.02 - 1e-6 <= x.min() < Table().radius


def test_the_saved_session_holds_them(played):
    program, _, _, _, _, save = played
    assert program.done and program.saved[0] == save
    loaded = Session.load(save)
    assert loaded.table.ball_diameter_m == 0.04
    assert loaded.table.cushion_restitution == 1.2


def test_a_restored_session_draws_the_new_ball_size(played, rainbow):
    save = played[5]
    program = Program(rainbow.client, restore=Session.load(save))
    feed(rainbow, program, "key r\nwait 1\n")
    assert program.view.table.ball_diameter_m == 0.04
    assert program.view.ball_radius_px == max(2, round(0.02 * program.view.scale))


def test_a_refused_size_says_why_and_changes_nothing(rainbow):
    program = Program(rainbow.client)
    feed(rainbow, program, BALL_SIZE.replace("0.04", "0.06"))
    assert program.session.table == Table()
    assert program.help_text.startswith("Not done:") and "overlap" in program.help_text
    assert screen_colour(rainbow, 10, 10) == hex_rgb("#ffb0b0")


def test_escape_and_return_keep_the_constants(rainbow):
    program = Program(rainbow.client)
    feed(rainbow, program, BALL_SIZE.replace("type 0.04\n", ""))
    assert program.session.table == Table() and "kept" in program.help_text


def test_friction_from_the_session():
    s = Session.new_game()
    s.change_table(deceleration_m_s2=0.5)
    s.strike(CUE, 1.0, 90.0)
    s.simulate_to_rest()
    slow = Session.new_game()
    slow.strike(CUE, 1.0, 90.0)
    slow.simulate_to_rest()
    assert s.timeline.time_frames[-1].balls.t < 0.6 * slow.timeline.time_frames[-1].balls.t


def test_the_session_refuses_what_cannot_be():
    s = Session.new_game()
    with pytest.raises(SessionError, match="frame rate"):
        s.change_table(frame_rate=50)
    with pytest.raises(SessionError, match="out of range"):
        s.change_table(cushion_restitution=-1.0)
    with pytest.raises(SessionError, match="fit between the cushions"):
        s.change_table(length_m=1.0)
    assert s.table == Table() and not s.timeline.event_frames


def test_the_change_is_an_event_and_old_frames_stay_unrecoverable():
    s = Session.new_game()
    s.strike(CUE, 1.0, 90.0)
    for _ in range(5):
        s.simulate_frame()
    s.goto_time_frame(2)
    s.change_table(cushion_restitution=1.5)
    assert s.frame.event is not None and "cushion_restitution=1.5" in s.frame.event.note
    assert len(s.timeline.time_frames) == 3
    assert not s.recover()  # frames simulated with the old constants are gone
