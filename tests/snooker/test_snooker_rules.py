"""Rules: a scripted frame of play with fouls, re-spotting onto occupied spots, the
colours-in-order end game, and consistency when going back in time."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.snooker.events import Event, EventKind
from camlab88.apps.snooker.layout import opening_state
from camlab88.apps.snooker.rules import (
    ON_COLOUR,
    ON_RED,
    GameState,
    Shot,
    adjudicate,
    apply_outcome,
    legal_to_hit,
    legal_to_pot,
    record,
    spot_position,
)
from camlab88.apps.snooker.session import Session
from camlab88.apps.snooker.table import (
    BLACK,
    BLUE,
    BROWN,
    COLOURS,
    CUE,
    GREEN,
    N_BALLS,
    PINK,
    REDS,
    YELLOW,
    Table,
)
from tests.snooker.helpers import state_with

T = Table()
ALL = np.ones(N_BALLS, dtype=bool)


def table_after(potted: tuple[int, ...], base: np.ndarray = ALL) -> np.ndarray:
    on = base.copy()
    on[list(potted)] = False
    return on


class Play:
    """Plays shots through `adjudicate`, tracking which balls are on the table."""

    def __init__(self, game: GameState | None = None, on: np.ndarray | None = None) -> None:
        self.game = game or GameState()
        self.on = ALL.copy() if on is None else on.copy()
        self.pos = np.array(opening_state(T).pos)

    def shot(self, first_hit: int, *potted: int):
        shot = Shot()
        if first_hit >= 0:
            shot = record(shot, Event(EventKind.BALL_BALL, 0.0, CUE, first_hit))
        for b in potted:
            shot = record(shot, Event(EventKind.POCKET, 0.0, b, 0))
        after = table_after(potted, self.on)
        out = adjudicate(self.game, shot, after)
        self.pos, self.on = apply_outcome(T, out, self.pos, after)
        self.game = out.game
        return out


def test_scripted_frame_of_play_with_fouls() -> None:
    p = Play()
    assert legal_to_hit(p.game) == frozenset(REDS)
    out = p.shot(REDS[10])  # the break-off: safe, nothing potted
    assert p.game.player == 1 and p.game.scores == (0, 0) and not out.fouls
    out = p.shot(REDS[0], REDS[0])  # player 2 pots a red
    assert p.game.scores == (0, 1) and p.game.player == 1 and p.game.on == ON_COLOUR
    assert p.game.current_break == 1
    # After a red any colour may be hit; the first colour hit becomes the only legal pot.
    assert legal_to_hit(p.game) == frozenset(COLOURS)
    shot = record(Shot(), Event(EventKind.BALL_BALL, 0.0, CUE, BLUE))
    assert legal_to_pot(p.game, shot) == frozenset({BLUE})
    out = p.shot(BLUE, BLUE)  # pots the blue: re-spotted, red on again
    assert p.game.scores == (0, 6) and p.game.current_break == 6 and out.respot == (BLUE,)
    assert p.on[BLUE] and tuple(p.pos[BLUE]) == T.spots[BLUE] and p.game.on == ON_RED
    out = p.shot(BLACK)  # hits the black first with red on: foul, 7 away
    assert out.fouls and out.penalty == 7 and p.game.scores == (7, 6)
    assert p.game.player == 0 and p.game.current_break == 0
    out = p.shot(REDS[1], REDS[1], PINK)  # red on: red and pink in together is a foul
    assert out.penalty == 6 and p.game.scores == (7, 12) and p.game.player == 1
    assert p.on[PINK] and not p.on[REDS[1]]  # colour re-spotted, the red stays down
    out = p.shot(REDS[2], REDS[2], CUE)  # in-off: foul 4, cue ball in hand in the D
    assert out.penalty == 4 and out.cue_in_hand and p.game.scores == (11, 12)
    assert T.in_d(*p.pos[CUE]) and p.on[CUE]
    out = p.shot(-1)  # misses everything
    assert out.fouls == ("failed to hit a ball",) and p.game.scores == (11, 16)
    p.shot(REDS[3], REDS[3])  # player 2 pots a red ...
    out = p.shot(GREEN, BLACK)  # ... hits the green but pots the black: foul, value 7
    assert out.penalty == 7 and p.game.scores == (18, 17) and p.on[BLACK]


def test_respot_onto_an_occupied_spot() -> None:
    pos = np.array(opening_state(T).pos)
    on = ALL.copy()
    on[BLACK] = False
    pos[REDS[0]] = T.spots[BLACK]  # a red sits on the black spot
    # Own spot taken: the highest-value free spot.  Pink is on its spot, so the blue's.
    pos[BLUE] = (1.0, 0.3)
    assert spot_position(T, pos, on, BLACK) == T.spots[BLUE]
    # Every spot taken: as near its own spot as possible towards the top cushion.
    pos[BLUE] = T.spots[BLUE]
    x, y = spot_position(T, pos, on, BLACK)
    assert y == T.spots[BLACK][1] and x > T.spots[BLACK][0]
    d = T.ball_diameter_m
    assert x - T.spots[BLACK][0] == pytest.approx(d, abs=d / 100)
    # ...and if that line is blocked to the cushion, towards the baulk cushion.
    for k in range(1, 7):  # a row of touching reds from the black spot to the cushion
        pos[REDS[k]] = (T.spots[BLACK][0] + k * T.ball_diameter_m, T.spots[BLACK][1])
    x2, _ = spot_position(T, pos, on, BLACK)
    assert x2 < T.spots[BLACK][0]


def test_two_colours_respotted_highest_first() -> None:
    p = Play(GameState(on=ON_COLOUR))
    p.pos[REDS[0]] = T.spots[YELLOW]
    p.pos[YELLOW] = (1.0, 0.3)
    p.on[BLACK] = False  # (a scripted position: the black spot is free)
    out = p.shot(PINK, PINK, YELLOW)  # nominated pink, the yellow also went in: foul
    assert out.respot == (PINK, YELLOW) and out.penalty == 6
    assert tuple(p.pos[PINK]) == T.spots[PINK]
    assert tuple(p.pos[YELLOW]) == T.spots[BLACK]  # its own spot taken by a red


def test_colours_in_order_end_game() -> None:
    on = ALL.copy()
    on[list(REDS)] = False
    on[REDS[0]] = True
    p = Play(GameState(), on)
    p.shot(REDS[0], REDS[0])  # the last red
    assert p.game.on == ON_COLOUR and p.game.scores == (1, 0)
    out = p.shot(BLACK, BLACK)  # the colour after the last red is re-spotted
    assert out.respot == (BLACK,) and p.game.on == YELLOW and p.game.scores == (8, 0)
    p.shot(YELLOW, YELLOW)
    assert not p.on[YELLOW] and p.game.on == GREEN  # the ball on stays down now
    out = p.shot(BROWN, BROWN)  # wrong colour: foul, brown re-spotted, turn passes
    assert out.penalty == 4 and p.on[BROWN] and p.game.player == 1 and p.game.on == GREEN
    for ball in (GREEN, BROWN, BLUE, PINK):
        p.shot(ball, ball)
        assert not p.on[ball]
    assert p.game.on == BLACK and not p.game.frame_over
    assert p.game.scores == (1 + 7 + 2, 4 + 3 + 4 + 5 + 6)
    p.shot(BLACK, BLACK)
    assert p.game.frame_over and p.game.scores == (10, 29) and "player 2 wins" in p.game.message
    assert legal_to_hit(p.game) == frozenset()


def test_tie_on_the_last_black_respots_it() -> None:
    on = np.zeros(N_BALLS, dtype=bool)
    on[[CUE, BLACK]] = True
    p = Play(GameState(scores=(10, 3), player=1, on=BLACK), on)
    out = p.shot(BLACK, BLACK)
    assert out.respot == (BLACK,) and not p.game.frame_over and p.on[BLACK]
    assert p.game.scores == (10, 10)


def test_foul_on_the_last_black_ends_the_frame() -> None:
    on = np.zeros(N_BALLS, dtype=bool)
    on[[CUE, BLACK]] = True
    p = Play(GameState(scores=(30, 3), on=BLACK), on)
    p.shot(-1)
    assert p.game.frame_over and p.game.scores == (30, 10)


def pot_a_red_session() -> tuple[Session, int]:
    """A red a few cm from the middle pocket and the cue ball lined up behind it."""
    red = REDS[0]
    s = state_with(T, {CUE: (T.length_m / 2, 0.5), red: (T.length_m / 2, 0.2)})
    sess = Session.new_game(T)
    sess.timeline.time_frames[0] = sess.timeline.time_frames[0].__class__(
        "time", 0, s, GameState(), None)
    return sess, red


def test_going_back_and_changing_the_outcome_keeps_score_consistent() -> None:
    sess, red = pot_a_red_session()
    sess.set_velocity(CUE, 0.0, -1.5)
    sess.simulate_to_rest()
    assert sess.status()["scores"] == (1, 0) and sess.status()["player"] == 1
    assert not sess.balls.on_table[red]
    pot_frame = next(f for f in sess.timeline.event_frames if f.event.kind == EventKind.POCKET)
    # Step back to before the pot: the display state is the one at that frame.
    sess.goto_time_frame(pot_frame.index)
    assert sess.status()["scores"] == (0, 0) and sess.frame.shot is not None
    # Back to the start and cheat: hit it too thin to pot.
    sess.goto_time_frame(0)
    sess.set_velocity(CUE, 0.2, -1.5)
    sess.simulate_to_rest()
    st = sess.status()
    assert sess.balls.on_table[red] and st["scores"] == (0, 0) and st["player"] == 2
    # The earlier outcome is recoverable.
    assert sess.recover() and sess.status()["scores"] == (1, 0)
