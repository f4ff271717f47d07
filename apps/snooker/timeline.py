"""State and time (§6.2, §6.2.2): a time frame every 1/25 s of simulated time and a
collision frame at every collision (and every other significant event), kept on two stacks.

Time frame n is at exactly n / frame_rate seconds.  An event frame belongs after the time
frame it follows (`index`), so the merged sequence is ordered by (index, time frame first,
then events in the order they happened).  Every frame carries the rules state too, so
stepping back shows a consistent score, and simulation can restart from any frame: the
later frames become invalid but are kept (`invalid`) so they can be recovered (§5.2.2
says invalid frames may be recovered from a checkpoint or by re-simulating; keeping them
in memory is ours).
Everything is deterministic: the same edits give bit-identical frames.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Literal

import numpy as np

from camlab88.apps.snooker.events import Event, EventKind
from camlab88.apps.snooker.physics import Physics, SimulationError, state_moving
from camlab88.apps.snooker.rules import GameState, Shot, adjudicate, apply_outcome, record
from camlab88.apps.snooker.state import BallState
from camlab88.apps.snooker.table import Table

Kind = Literal["time", "event"]
Unit = Literal["frame", "event"]


@dataclass(frozen=True)
class Frame:
    kind: Kind
    index: int  # time-frame number (an event frame: the time frame it follows)
    balls: BallState
    game: GameState
    shot: Shot | None  # None between shots
    event: Event | None = None


@dataclass(frozen=True)
class Cursor:
    """A place in the merged sequence: ("time", n) or ("event", position on the stack)."""

    kind: Kind
    pos: int


@dataclass(frozen=True)
class Discarded:
    """Frames made invalid by restarting from `after`, kept for recovery."""

    after: Cursor
    time_frames: tuple[Frame, ...]
    event_frames: tuple[Frame, ...]
    replaced: Frame | None = None  # the edited frame as it was before the edit


class Timeline:
    def __init__(self, table: Table, start: BallState, game: GameState | None = None) -> None:
        self.table = table
        self.physics = Physics(table)
        game = game or GameState()
        if start.t != 0.0:
            start = replace(start, t=0.0)
        shot = Shot() if state_moving(start.thaw()) else None
        self.time_frames: list[Frame] = [Frame("time", 0, start, game, shot)]
        self.event_frames: list[Frame] = []
        self.invalid: list[Discarded] = []

    # --- navigation ------------------------------------------------------------------
    def frame(self, c: Cursor) -> Frame:
        return (self.time_frames if c.kind == "time" else self.event_frames)[c.pos]

    def order(self) -> list[Cursor]:
        """The merged sequence of time and event frames."""
        out: list[Cursor] = []
        e = 0
        for n in range(len(self.time_frames)):
            out.append(Cursor("time", n))
            while e < len(self.event_frames) and self.event_frames[e].index == n:
                out.append(Cursor("event", e))
                e += 1
        return out

    @property
    def head(self) -> Cursor:
        if self.event_frames and self.event_frames[-1].index >= len(self.time_frames) - 1:
            return Cursor("event", len(self.event_frames) - 1)
        return Cursor("time", len(self.time_frames) - 1)

    def step(self, c: Cursor, delta: int, unit: Unit = "frame") -> Cursor:
        """Move `delta` frames (time and collision frames alike) or significant events;
        stops at either end."""
        seq = self.order()
        i = seq.index(c)
        if unit == "frame":
            return seq[max(0, min(len(seq) - 1, i + delta))]
        marks = [k for k, q in enumerate(seq) if q.kind == "event"]
        if delta > 0:
            later = [k for k in marks if k > i]
            return seq[later[delta - 1]] if len(later) >= delta else seq[-1]
        if delta < 0:
            earlier = [k for k in marks if k < i]
            return seq[earlier[delta]] if len(earlier) >= -delta else seq[0]
        return c

    # --- simulation ------------------------------------------------------------------
    def simulate_frame(self) -> list[Frame]:
        """Simulate from the head to the next time frame; returns the frames added (event
        frames then the time frame).  When everything has come to rest the shot is
        adjudicated: colours re-spotted, the score updated and a SHOT_END event added."""
        return self.simulate(1)

    def simulate(self, max_frames: int) -> list[Frame]:
        """As `simulate_frame`, for up to `max_frames` time frames (stops at rest)."""
        head = self.frame(self.head)
        m = head.balls.thaw()
        added: list[Frame] = []
        if not state_moving(m):
            if head.shot is not None:
                added.append(self._end_shot(head, head.index, replace_time=False))
            return added
        n = head.index
        shot = head.shot
        game = head.game
        last: Frame = head
        for ev, balls in self.physics.run(m, n + 1, max_frames):
            if ev is None:
                n += 1
                last = Frame("time", n, balls, game, shot)
                self.time_frames.append(last)
            else:
                if shot is not None:
                    shot = record(shot, ev)
                last = Frame("event", n, balls, game, shot, ev)
                self.event_frames.append(last)
            added.append(last)
        if last.kind == "time" and not state_moving(m) and shot is not None:
            end = self._end_shot(last, n, replace_time=True)
            added[-1] = self.time_frames[n]  # the rest frame, now with colours re-spotted
            added.append(end)
        return added

    def _end_shot(self, f: Frame, n: int, replace_time: bool) -> Frame:
        assert f.shot is not None
        outcome = adjudicate(f.game, f.shot, f.balls.on_table)
        pos, on_table = apply_outcome(self.table, outcome, np.array(f.balls.pos),
                                      np.array(f.balls.on_table))
        m = f.balls.thaw()
        m.pos[:] = pos
        m.on_table[:] = on_table
        balls = m.freeze()
        if replace_time:
            self.time_frames[n] = Frame("time", n, balls, outcome.game, None)
        ev = Event(EventKind.SHOT_END, balls.t, note=outcome.game.message)
        ef = Frame("event", n, balls, outcome.game, None, ev)
        self.event_frames.append(ef)
        return ef

    def simulate_to_rest(self, max_seconds: float = 600.0) -> None:
        start = self.frame(self.head).balls.t
        while True:
            added = self.simulate(250)
            if not added or added[-1].event is not None \
                    and added[-1].event.kind == EventKind.SHOT_END:
                return
            if self.time_frames[-1].balls.t - start > max_seconds:
                raise SimulationError(f"balls still moving after {max_seconds} s")

    # --- restarting ------------------------------------------------------------------
    def _cut(self, c: Cursor) -> tuple[tuple[Frame, ...], tuple[Frame, ...]]:
        f = self.frame(c)
        if c.kind == "time":
            keep_t, keep_e = c.pos + 1, sum(1 for e in self.event_frames if e.index < c.pos)
        else:
            keep_t, keep_e = f.index + 1, c.pos + 1
        tail = (tuple(self.time_frames[keep_t:]), tuple(self.event_frames[keep_e:]))
        del self.time_frames[keep_t:]
        del self.event_frames[keep_e:]
        return tail

    def truncate_after(self, c: Cursor, replaced: Frame | None = None) -> None:
        """Make every frame after `c` invalid (kept in `self.invalid` for recovery)."""
        tail_t, tail_e = self._cut(c)
        self.invalid.append(Discarded(c, tail_t, tail_e, replaced))

    def intervene(self, c: Cursor, balls: BallState, note: str) -> Cursor:
        """The animator changed the state at frame `c`: later frames become invalid and the
        change is recorded as a significant event; simulation continues from it."""
        f = self.frame(c)
        if not math.isclose(balls.t, f.balls.t, rel_tol=0, abs_tol=1e-12):
            raise ValueError("an intervention must keep the frame's time")
        shot = f.shot
        if shot is None and state_moving(balls.thaw()):
            shot = Shot()  # setting a ball moving between shots plays a new shot
        self.truncate_after(c, replaced=f if c.kind == "time" else None)
        if c.kind == "time":  # the time frame itself shows the change (it is filmed)
            self.time_frames[c.pos] = Frame("time", c.pos, balls, f.game, shot)
        ev = Event(EventKind.INTERVENTION, balls.t, note=note)
        self.event_frames.append(Frame("event", f.index, balls, f.game, shot, ev))
        return Cursor("event", len(self.event_frames) - 1)

    def change_table(self, c: Cursor, table: Table, note: str) -> Cursor:
        """The animator altered the table's constants at frame `c` (§6.2: they "may be
        altered by the animator"): from `c` on the simulation uses `table`.  The change is a
        significant event; the later frames become invalid and, having been simulated with
        the old constants, cannot be recovered (nor can older invalid frames)."""
        at = self.intervene(c, self.frame(c).balls, note)
        self.table = table
        self.physics = Physics(table)
        self.invalid.clear()
        return at

    def recover(self) -> bool:
        """Undo the most recent restart: the frames made invalid come back and what was
        simulated since is dropped.  False if there is nothing to recover."""
        if not self.invalid:
            return False
        d = self.invalid.pop()
        self._cut(d.after)
        if d.replaced is not None:
            self.time_frames[d.after.pos] = d.replaced
        self.time_frames.extend(d.time_frames)
        self.event_frames.extend(d.event_frames)
        return True
