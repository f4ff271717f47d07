"""The rules of the game (§6.1.1, §6.2): whose turn it is, the scores, the current break,
which balls are legal to hit and to pot, fouls and penalties, re-spotting (including an
occupied spot) and the end of the frame.

Everything here is a pure function of an immutable `GameState` (between shots) and a `Shot`
(what has happened so far in the shot being played).  The timeline stores both in every
frame, so stepping back in time and changing an outcome re-derives the score from the state
at that frame: the scoring cannot be confused (§6.2.2).

Where the thesis gives no detail (penalty values, the spot rules for an occupied spot, the
cue ball in hand) the official rules of snooker are followed, simplified as listed in
docs/fidelity/snooker.md.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from camlab88.apps.snooker.events import Event, EventKind
from camlab88.apps.snooker.layout import default_cue_position
from camlab88.apps.snooker.table import (
    BALL_NAMES,
    BALL_VALUES,
    BLACK,
    COLOURS,
    CUE,
    N_BALLS,
    REDS,
    Table,
    is_red,
)

ON_RED = -1  # ball on: any red
ON_COLOUR = -2  # ball on: any colour (after a red); the first colour hit is nominated
MIN_PENALTY = 4
SPOT_CLEARANCE_M = 1e-6  # a re-spotted ball must not touch another


def describe_on(on: int) -> str:
    if on == ON_RED:
        return "red"
    if on == ON_COLOUR:
        return "any colour"
    return BALL_NAMES[on]


@dataclass(frozen=True)
class GameState:
    """The game between shots."""

    scores: tuple[int, int] = (0, 0)
    player: int = 0  # whose turn: 0 or 1
    current_break: int = 0
    on: int = ON_RED
    shots: int = 0
    frame_over: bool = False
    message: str = "Player 1 to break off"

    def to_json(self) -> dict[str, object]:
        return {"scores": list(self.scores), "player": self.player,
                "current_break": self.current_break, "on": self.on, "shots": self.shots,
                "frame_over": self.frame_over, "message": self.message}

    @classmethod
    def from_json(cls, d: dict[str, object]) -> GameState:
        scores = tuple(int(x) for x in d["scores"])
        if len(scores) != 2 or int(d["player"]) not in (0, 1):
            raise ValueError("bad scores or player")
        return cls(scores, int(d["player"]), int(d["current_break"]),
                   int(d["on"]), int(d["shots"]), bool(d["frame_over"]), str(d["message"]))


@dataclass(frozen=True)
class Shot:
    """What has happened so far in the shot being played."""

    first_hit: int = -1  # first ball the cue ball touched
    potted: tuple[int, ...] = field(default=())  # in the order they dropped

    def to_json(self) -> dict[str, object]:
        return {"first_hit": self.first_hit, "potted": list(self.potted)}

    @classmethod
    def from_json(cls, d: dict[str, object]) -> Shot:
        return cls(int(d["first_hit"]), tuple(int(x) for x in d["potted"]))


def record(shot: Shot, event: Event) -> Shot:
    """Fold one physics event into the shot."""
    if event.kind == EventKind.BALL_BALL and shot.first_hit < 0 and CUE in (event.a, event.b):
        return replace(shot, first_hit=event.b if event.a == CUE else event.a)
    if event.kind == EventKind.POCKET:
        return replace(shot, potted=shot.potted + (event.a,))
    return shot


def nominated(game: GameState, shot: Shot) -> int:
    """The colour that has become the only legal pot (the first colour hit), or -1."""
    if game.on == ON_COLOUR and shot.first_hit >= 0 and not is_red(shot.first_hit):
        return shot.first_hit
    return -1


def legal_to_hit(game: GameState, shot: Shot | None = None) -> frozenset[int]:
    """Balls the cue ball may legally hit first."""
    if game.frame_over:
        return frozenset()
    if game.on == ON_RED:
        return frozenset(REDS)
    if game.on == ON_COLOUR:
        return frozenset(COLOURS)
    return frozenset({game.on})


def legal_to_pot(game: GameState, shot: Shot | None = None) -> frozenset[int]:
    """Balls that may legally be potted now; once a colour has been hit after a red it is
    the only one (§6.2)."""
    shot = shot or Shot()
    nom = nominated(game, shot)
    if nom >= 0:
        return frozenset({nom})
    return legal_to_hit(game, shot)


@dataclass(frozen=True)
class Outcome:
    game: GameState
    respot: tuple[int, ...]  # colours to put back, in the order they are spotted
    cue_in_hand: bool
    fouls: tuple[str, ...]
    points: int  # to the striker (0 on a foul)
    penalty: int  # to the opponent


def adjudicate(game: GameState, shot: Shot, on_table_after: np.ndarray) -> Outcome:
    """Score a finished shot.  `on_table_after` is which balls are still on the table."""
    if game.frame_over:
        return Outcome(game, (), False, (), 0, 0)
    on = game.on
    nom = nominated(game, shot)
    fouls: list[str] = []
    values = [MIN_PENALTY]
    if on >= 0:
        values.append(BALL_VALUES[on])
    elif nom >= 0:
        values.append(BALL_VALUES[nom])
    hit = shot.first_hit
    if hit < 0:
        fouls.append("failed to hit a ball")
    elif hit not in legal_to_hit(game):
        fouls.append(f"hit the {BALL_NAMES[hit]} first, {describe_on(on)} was on")
        values.append(BALL_VALUES[hit])
    legal = legal_to_pot(game, shot)
    scored = 0
    for b in shot.potted:
        if b == CUE:
            fouls.append("cue ball potted")
        elif b in legal and hit in legal_to_hit(game):
            scored += BALL_VALUES[b]
        else:
            fouls.append(f"potted the {BALL_NAMES[b]} illegally")
            values.append(BALL_VALUES[b])
    striker, other = game.player, 1 - game.player
    reds_left = int(sum(on_table_after[r] for r in REDS))
    scores = list(game.scores)
    respot = [b for b in shot.potted if b in COLOURS]
    if on >= 0 and not fouls and on in shot.potted:
        respot.remove(on)  # in the end game the ball on stays down
    if fouls:
        penalty = max(values)
        scores[other] += penalty
        if on == BLACK:  # only the black left: the first score or foul ends the frame
            respot = [b for b in respot if b != BLACK]
        nxt = replace(game, scores=(scores[0], scores[1]), player=other, current_break=0,
                      message=f"Foul ({'; '.join(fouls)}): {penalty} to player {other + 1}")
        points = 0
    elif scored:
        penalty = 0
        scores[striker] += scored
        nxt = replace(game, scores=(scores[0], scores[1]),
                      current_break=game.current_break + scored,
                      message=f"Player {striker + 1} scores {scored}")
        points = scored
    else:
        penalty = points = 0
        nxt = replace(game, player=other, current_break=0,
                      message=f"No score: player {other + 1} to play")
    colours_left = [c for c in COLOURS if on_table_after[c] or c in respot]
    continuing = not fouls and scored > 0
    if continuing and on == ON_RED:
        new_on = ON_COLOUR
    elif continuing and on == ON_COLOUR:
        new_on = ON_RED if reds_left else COLOURS[0]
    elif reds_left:
        new_on = ON_RED
    else:
        new_on = colours_left[0] if colours_left else -3
    if new_on >= 0 and new_on not in colours_left:
        new_on = colours_left[0] if colours_left else -3
    frame_over = new_on == -3 or (on == BLACK and bool(fouls or scored))
    if frame_over and nxt.scores[0] == nxt.scores[1]:
        # Tie on the last black: it is re-spotted and the frame goes on (official rule; the
        # player to take the re-spotted black is the one who did not end the frame).
        respot = [BLACK]
        new_on, frame_over = BLACK, False
        nxt = replace(nxt, player=other, current_break=0, message="Scores tied: black re-spotted")
    if frame_over:
        winner = 0 if nxt.scores[0] > nxt.scores[1] else 1
        nxt = replace(nxt, message=nxt.message + f"; frame over, player {winner + 1} wins")
    respot.sort(key=lambda b: -BALL_VALUES[b])  # the highest value is spotted first
    nxt = replace(nxt, on=max(new_on, -2) if not frame_over else game.on, shots=game.shots + 1,
                  frame_over=frame_over)
    return Outcome(nxt, tuple(respot), CUE in shot.potted, tuple(fouls), points, penalty)


def _free(pos: np.ndarray, on_table: np.ndarray, x: float, y: float, d: float,
          ignore: int) -> bool:
    for i in range(N_BALLS):
        if i != ignore and on_table[i]:
            if math.hypot(pos[i, 0] - x, pos[i, 1] - y) < d + SPOT_CLEARANCE_M:
                return False
    return True


def spot_position(table: Table, pos: np.ndarray, on_table: np.ndarray, ball: int
                  ) -> tuple[float, float]:
    """Where a potted colour is re-spotted: its own spot; if that is occupied the highest
    value spot available; if all are occupied, as near its own spot as possible on the line
    from it towards the top cushion, else towards the baulk cushion."""
    d, r = table.ball_diameter_m, table.radius
    own = table.spots[ball]
    if _free(pos, on_table, *own, d, ball):
        return own
    for c in reversed(COLOURS):
        if _free(pos, on_table, *table.spots[c], d, ball):
            return table.spots[c]
    step = d / 200.0
    for direction, limit in ((1.0, table.length_m - r), (-1.0, r)):
        x = own[0]
        while (x - limit) * direction <= 0:
            if _free(pos, on_table, x, own[1], d, ball):
                return (x, own[1])
            x += direction * step
    raise ValueError(f"nowhere to re-spot the {BALL_NAMES[ball]}")


def cue_in_hand_position(table: Table, pos: np.ndarray, on_table: np.ndarray
                         ) -> tuple[float, float]:
    """The incoming player's cue ball goes in the D (default spot; the animator may move it);
    if that is occupied, the nearest free point across the D."""
    x, y = default_cue_position(table)
    d = table.ball_diameter_m
    step = d / 50.0
    for k in range(0, 2000):
        for sign in (1.0, -1.0):
            yy = y + sign * k * step
            if table.in_d(x, yy) and _free(pos, on_table, x, yy, d, CUE):
                return (x, yy)
    raise ValueError("no room for the cue ball in the D")


def apply_outcome(table: Table, outcome: Outcome, pos: np.ndarray, on_table: np.ndarray
                  ) -> tuple[np.ndarray, np.ndarray]:
    """Positions and on-table flags after re-spotting (and the cue ball in hand)."""
    pos = pos.copy()
    on_table = on_table.copy()
    for b in outcome.respot:
        pos[b] = spot_position(table, pos, on_table, b)
        on_table[b] = True
    if outcome.cue_in_hand:
        pos[CUE] = cue_in_hand_position(table, pos, on_table)
        on_table[CUE] = True
    return pos, on_table


def infer_game(on_table: np.ndarray) -> GameState:
    """A plausible game state for a position with no history (e.g. from a checkpoint)."""
    if any(on_table[r] for r in REDS):
        return GameState(message="Position loaded: red on")
    left = [c for c in COLOURS if on_table[c]]
    if not left:
        return GameState(frame_over=True, message="No balls left")
    return GameState(on=left[0], message=f"Position loaded: {BALL_NAMES[left[0]]} on")
