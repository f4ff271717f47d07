"""A motion-development session: the table, the timeline and where the animator is in it.
This is the API the interactive program drives (select a ball, set its position, velocity
and spin, simulate, step back and forth, restart from a frame, aim), and it saves to and
restores from a session file so a sequence can be developed over several sittings
(§6.2.2: "begin a new game or restore the situation from an earlier session").

The session file is JSON (format "camlab88-snooker-session", version 1) holding the table
constants and both frame stacks in full, so a restored session steps back through the
earlier frames exactly as before.
"""

from __future__ import annotations

import dataclasses
import json
import math
import os
from dataclasses import replace

import numpy as np

from camlab88.apps.snooker import aiming, checkpoint
from camlab88.apps.snooker.events import Event, EventKind
from camlab88.apps.snooker.layout import opening_state
from camlab88.apps.snooker.rules import GameState, Shot, infer_game, legal_to_hit, legal_to_pot
from camlab88.apps.snooker.state import BallState
from camlab88.apps.snooker.table import BALL_NAMES, Table
from camlab88.apps.snooker.timeline import Cursor, Frame, Timeline, Unit
from camlab88.base.atomicfile import write_atomic
from camlab88.base.textinput import quote, read_json

FORMAT = "camlab88-snooker-session"
VERSION = 1


class SessionError(ValueError):
    pass


class Session:
    def __init__(self, timeline: Timeline, cursor: Cursor | None = None) -> None:
        self.timeline = timeline
        self.cursor = cursor or timeline.head

    # --- starting --------------------------------------------------------------------
    @classmethod
    def new_game(cls, table: Table | None = None) -> Session:
        table = table or Table()
        return cls(Timeline(table, opening_state(table)))

    @classmethod
    def from_positions(cls, table: Table, pos: np.ndarray) -> Session:
        """A position with no history (e.g. the last frame of a checkpoint): balls at rest,
        those outside the playing area potted, the rules state inferred."""
        on = np.array([table.on_playing_area(x, y) for x, y in pos])
        balls = BallState.at_rest(pos, on)
        return cls(Timeline(table, balls, infer_game(on)))

    @classmethod
    def from_checkpoint(cls, path: str | os.PathLike[str], table: Table | None = None) -> Session:
        cp = checkpoint.read(path)
        return cls.from_positions(table or Table(), checkpoint.to_metres(cp.positions[-1]))

    # --- what the display shows ------------------------------------------------------
    @property
    def table(self) -> Table:
        return self.timeline.table

    @property
    def frame(self) -> Frame:
        return self.timeline.frame(self.cursor)

    @property
    def balls(self) -> BallState:
        return self.frame.balls

    @property
    def frame_number(self) -> int:
        return self.frame.index

    @property
    def collision_number(self) -> int:
        """Collisions so far up to the current frame (ball-ball and cushion)."""
        seq = self.timeline.order()
        upto = seq[: seq.index(self.cursor) + 1]
        kinds = (EventKind.BALL_BALL, EventKind.CUSHION, EventKind.JAW)
        return sum(
            1 for c in upto if c.kind == "event"
            and self.timeline.event_frames[c.pos].event is not None
            and self.timeline.event_frames[c.pos].event.kind in kinds
        )

    def status(self) -> dict[str, object]:
        f = self.frame
        shot = f.shot or Shot()
        return {
            "frame": f.index, "time": f.balls.t, "collision": self.collision_number,
            "player": f.game.player + 1, "scores": f.game.scores, "break": f.game.current_break,
            "legal_to_hit": sorted(legal_to_hit(f.game, shot)),
            "legal_to_pot": sorted(legal_to_pot(f.game, shot)),
            "message": f.game.message, "frame_over": f.game.frame_over,
        }

    def select_ball_at(self, x: float, y: float) -> int | None:
        """The ball under the cursor, if any (the nearest whose disc contains the point)."""
        b = self.balls
        best, best_d = None, math.inf
        for i in range(len(BALL_NAMES)):
            d = math.hypot(b.pos[i, 0] - x, b.pos[i, 1] - y)
            if d <= self.table.radius and d < best_d:
                best, best_d = i, d
        return best

    # --- changing the current frame (each change is a significant event) ------------
    def _edit(self, note: str, **changes: object) -> None:
        m = self.balls.thaw()
        fn = changes.pop("fn")
        fn(m)
        self.cursor = self.timeline.intervene(self.cursor, m.freeze(), note)

    def set_position(self, ball: int, x: float, y: float) -> None:
        """Move a ball; outside the playing area means potted (off the table)."""
        if not (math.isfinite(x) and math.isfinite(y)):
            raise SessionError("position must be finite")
        on = self.table.on_playing_area(x, y)

        def fn(m):
            m.pos[ball] = (x, y)
            m.on_table[ball] = on
            if not on:
                m.set_velocity(ball, 0.0, 0.0)

        self._edit(f"{BALL_NAMES[ball]} moved to ({x:.4f}, {y:.4f})", fn=fn)

    def set_velocity(self, ball: int, vx: float, vy: float, spin: float = 0.0) -> None:
        if not all(math.isfinite(v) for v in (vx, vy, spin)):
            raise SessionError("velocity and spin must be finite")
        if not self.balls.on_table[ball]:
            raise SessionError(f"the {BALL_NAMES[ball]} is not on the table")
        if math.hypot(vx, vy) + abs(spin) > self.table.max_speed_m_s:
            raise SessionError(f"faster than the table's max_speed_m_s "
                               f"({self.table.max_speed_m_s:g} m/s)")
        self._edit(f"{BALL_NAMES[ball]} velocity ({vx:.3f}, {vy:.3f}) spin {spin:.3f}",
                   fn=lambda m: m.set_velocity(ball, vx, vy, spin))

    def strike(self, ball: int, speed: float, angle_deg: float, spin: float = 0.0) -> None:
        """Velocity by speed and direction (degrees anticlockwise from up the table)."""
        a = math.radians(angle_deg)
        self.set_velocity(ball, speed * math.cos(a), speed * math.sin(a), spin)

    def stop_all(self) -> None:
        def fn(m):
            for i in range(len(BALL_NAMES)):
                m.set_velocity(i, 0.0, 0.0)

        self._edit("all balls stopped", fn=fn)

    def change_table(self, **changes: float) -> Table:
        """Alter table constants (ball size, cushion restitution, friction, table size) from
        the current frame on (§6.2; §6.5: "different sizes of balls and different
        coefficients of restitution for the cushions"); the table view and the saved session
        then use the new constants.  Refused if a ball on the table would no longer fit."""
        if "frame_rate" in changes:  # time frame n is at n / frame_rate: fixed for a session
            raise SessionError("the frame rate cannot change during a session")
        try:
            table = check_table(replace(self.table, **changes))
        except (TypeError, ValueError) as exc:
            raise SessionError(_reason(exc)) from None
        _check_balls_fit(table, self.balls)
        note = "table: " + ", ".join(f"{k}={v:g}" for k, v in changes.items())
        self.cursor = self.timeline.change_table(self.cursor, table, note)
        return table

    # --- aiming ----------------------------------------------------------------------
    def aim_to_pot(self, ball: int, x: float, y: float) -> aiming.Aim:
        """Aim at the pocket nearest the point (x, y) the animator indicated."""
        return aiming.aim_to_pot(self.table, self.balls, ball,
                                 aiming.nearest_pocket(self.table, x, y))

    def aim_next_shot(self, ball: int, target: tuple[float, float], speed: float = 0.0,
                      cushions: tuple[str, ...] = ()) -> aiming.Aim:
        return aiming.aim_next_shot(self.table, self.balls, ball, target, speed, cushions)

    def accept_aim(self, aim: aiming.Aim) -> None:
        """Use a computed velocity (after the animator confirmed old vs new)."""
        self.set_velocity(aim.ball, *aim.velocity, 0.0)

    # --- time ------------------------------------------------------------------------
    def restart_here(self) -> None:
        """Make the frames after the current one invalid (recoverable)."""
        if self.cursor != self.timeline.head:
            self.timeline.truncate_after(self.cursor)
        self.cursor = self.timeline.head

    def simulate_frame(self) -> list[Frame]:
        """One more time frame from the current frame (restarting there if it is not the
        latest); the cursor follows."""
        self.restart_here()
        added = self.timeline.simulate_frame()
        self.cursor = self.timeline.head
        return added

    def simulate_to_rest(self, max_seconds: float = 600.0) -> None:
        self.restart_here()
        self.timeline.simulate_to_rest(max_seconds)
        self.cursor = self.timeline.head

    def step(self, delta: int, unit: Unit = "frame") -> Frame:
        self.cursor = self.timeline.step(self.cursor, delta, unit)
        return self.frame

    def goto_time_frame(self, n: int) -> Frame:
        if not 0 <= n < len(self.timeline.time_frames):
            raise SessionError(f"no time frame {n}")
        self.cursor = Cursor("time", n)
        return self.frame

    def recover(self) -> bool:
        ok = self.timeline.recover()
        self.cursor = self.timeline.head
        return ok

    # --- files -----------------------------------------------------------------------
    def checkpoint(self, first: int = 0, last: int | None = None) -> checkpoint.Checkpoint:
        frames = self.timeline.time_frames
        last = len(frames) - 1 if last is None else last
        if not 0 <= first <= last < len(frames):
            raise SessionError(f"frames {first}..{last} are not within 0..{len(frames) - 1}")
        table = self.timeline.table
        return checkpoint.Checkpoint.from_metres([f.balls.pos for f in frames[first : last + 1]],
                                                 (table.length_m, table.width_m))

    def to_json(self) -> dict[str, object]:
        tl = self.timeline
        return {
            "format": FORMAT, "version": VERSION,
            "table": dataclasses.asdict(tl.table),
            "cursor": [self.cursor.kind, self.cursor.pos],
            "time_frames": [_frame_json(f) for f in tl.time_frames],
            "event_frames": [_frame_json(f) for f in tl.event_frames],
        }

    def save(self, path: str | os.PathLike[str]) -> None:
        write_atomic(path, json.dumps(self.to_json(), separators=(",", ":")))

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> Session:
        data = read_json(path, SessionError)
        try:
            return cls.from_json(data)
        except SessionError as exc:
            raise SessionError(f"{path}: {exc}") from None

    @classmethod
    def from_json(cls, data: object) -> Session:
        if not isinstance(data, dict) or data.get("format") != FORMAT:
            raise SessionError(f"not a snooker session file (format {FORMAT!r} expected)")
        if data.get("version") != VERSION:
            raise SessionError(f"unsupported session version {quote(data.get('version'))}")
        if not isinstance(data.get("table"), dict):
            raise SessionError("'table' must be an object of table constants")
        try:
            table = Table(**data["table"])
        except (TypeError, ValueError) as exc:
            raise SessionError(f"table: {_reason(exc)}") from None
        check_table(table)
        tl = Timeline(table, opening_state(table))
        tl.time_frames = _frames(data, "time_frames", "time")
        tl.event_frames = _frames(data, "event_frames", "event")
        if not tl.time_frames:
            raise SessionError("no time frames")
        for n, f in enumerate(tl.time_frames):
            if f.index != n:
                raise SessionError(f"time_frames[{n}]: index {f.index} out of sequence")
        try:
            kind, pos = data["cursor"]
            cursor = Cursor(kind, int(pos))
            tl.frame(cursor)
            if kind not in ("time", "event") or pos < 0:
                raise ValueError
        except (TypeError, ValueError, KeyError, IndexError):
            raise SessionError(f"bad cursor {quote(data.get('cursor'))}") from None
        return cls(tl, cursor)


# The thesis's display shows 12 frames/s and a checkpoint replays at 25 (§6.2.2, §6.4); a
# session asking for more than this many frames per simulated second is not one the program
# could show, and a frame rate of 10^9 would fill memory with frames.
MAX_FRAME_RATE = 1000


def check_table(table: Table) -> Table:
    """Refuse table constants that ask for unbounded work (today: the frame rate); the
    command line's ``--table`` overrides go through this too."""
    if not 1 <= table.frame_rate <= MAX_FRAME_RATE:
        raise SessionError(f"table: frame_rate {table.frame_rate} is outside 1..{MAX_FRAME_RATE}")
    return table


def _check_balls_fit(table: Table, balls: BallState) -> None:
    """Every ball on the table must lie clear of the cushions and of the other balls at the
    new size; otherwise the collision equations of §6.2 have no valid first root."""
    r, eps = table.radius, 1e-9
    on = [i for i in range(len(BALL_NAMES)) if balls.on_table[i]]
    for i in on:
        x, y = balls.pos[i]
        if not (r - eps <= x <= table.length_m - r + eps
                and r - eps <= y <= table.width_m - r + eps):
            raise SessionError(f"the {BALL_NAMES[i]} would not fit between the cushions")
    for k, i in enumerate(on):
        for j in on[k + 1:]:
            d = math.hypot(*(balls.pos[i] - balls.pos[j]))
            if d < 2 * r - eps:
                raise SessionError(f"the {BALL_NAMES[i]} and the {BALL_NAMES[j]} would "
                                   f"overlap ({d:.4f} m apart, diameter {2 * r:.4f} m)")


def _reason(exc: BaseException) -> str:
    """An exception's own message, or what it means when Python's is cryptic."""
    text = str(exc)
    if isinstance(exc, OverflowError):
        return "a number too large for the format"
    if isinstance(exc, (TypeError, AttributeError)) or not text:
        return "a field has the wrong type (see docs/reliability.md for the format)"
    return text


def _frame_json(f: Frame) -> dict[str, object]:
    ev = None
    if f.event is not None:
        ev = {"kind": f.event.kind.name, "t": f.event.t, "a": f.event.a, "b": f.event.b,
              "chain": list(f.event.chain), "note": f.event.note}
    return {"index": f.index, "balls": f.balls.to_json(), "game": f.game.to_json(),
            "shot": None if f.shot is None else f.shot.to_json(), "event": ev}


def _frames(data: dict[str, object], key: str, kind: str) -> list[Frame]:
    raw = data.get(key)
    if not isinstance(raw, list):
        raise SessionError(f"{key} missing")
    out = []
    for k, d in enumerate(raw):
        try:
            ev = None
            if d["event"] is not None:
                e = d["event"]
                ev = Event(EventKind[e["kind"]], float(e["t"]), int(e["a"]), int(e["b"]),
                           tuple(int(x) for x in e["chain"]), str(e["note"]))
            shot = None if d["shot"] is None else Shot.from_json(d["shot"])
            f = Frame(kind, int(d["index"]), BallState.from_json(d["balls"]),
                      GameState.from_json(d["game"]), shot, ev)
        except KeyError as exc:
            raise SessionError(f"{key}[{k}]: missing {exc}") from None
        except (TypeError, ValueError, OverflowError, AttributeError) as exc:
            raise SessionError(f"{key}[{k}]: {_reason(exc)}") from None
        if kind == "event" and ev is None:
            raise SessionError(f"{key}[{k}]: an event frame without its event")
        out.append(replace(f))
    return out
