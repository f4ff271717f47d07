"""The CCL interpreter (thesis §6.3.1): commands in order, each over its period, giving an
observer, viewpoint and focal length for every frame.

Semantics (docs/snooker.md states them for users):
- A command's period is inclusive.  It starts at its FROM event, else the frame after the
  previous command's end (frame 1 for the first); it ends at its UNTIL event.  Events are
  looked for at or after the frame after the previous command's end (FROM) or the start
  (UNTIL).  A command with no time sub-command runs to END; one that only defines cameras
  or COORDS takes no time at all.
- A command's CAMERA and COORDS definitions take effect first, in the order written, then
  its OBSERVER, VIEWPOINT and FOCAL LENGTH over its period; a later command overrides an
  earlier one on the frames both cover.
- Values not set keep their previous value (before, during and after periods); before
  anything sets them, the start-of-day defaults hold (names.py).
- MOVING FROM a TO b and FOCAL LENGTH FROM a TO b are linear in frame number, a at the
  period's first frame and b at its last (b on a one-frame period); a name in AT or MOVING
  means where it is at the period's first frame; FOLLOWING uses the ball in each frame.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from camlab88.apps.snooker.camera import names, space
from camlab88.apps.snooker.camera.errors import CclError
from camlab88.apps.snooker.camera.motion import Motion
from camlab88.apps.snooker.camera.names import Unresolved, World
from camlab88.apps.snooker.camera.syntax import Command, Coord, CoordsDef, Focal, Name, Place, Time
from camlab88.apps.snooker.camera.views import View


@dataclass
class Interpretation:
    """Per-frame values (row f-1 is frame f) and every error found."""

    observer: np.ndarray  # (F, 3)
    viewpoint: np.ndarray  # (F, 3)
    focal: np.ndarray  # (F,)
    command_line: np.ndarray  # (F,) the script line of the command that set frame f (0: none)
    periods: list[tuple[int, int, int]] = field(default_factory=list)  # (line, first, last)
    errors: list[CclError] = field(default_factory=list)

    def views(self) -> list[View]:
        o, v, f = self.observer.tolist(), self.viewpoint.tolist(), self.focal.tolist()
        return [View(i + 1, tuple(o[i]), tuple(v[i]), f[i])
                for i in range(len(f))]


class _Run:
    def __init__(self, motion: Motion) -> None:
        n = motion.n_frames
        self.world = World(motion)
        self.obs = np.full((n, 3), np.nan)
        self.vp = np.full((n, 3), np.nan)
        self.focal = np.full(n, np.nan)
        self.owner = np.zeros(n, dtype=np.int64)  # index into self.tokens, 0: none
        self.tokens: list[object] = [None]
        self.periods: list[tuple[int, int, int]] = []
        self.errors: list[CclError] = []
        self.prev_end = 0

    def error(self, tok: object, message: str) -> None:
        self.errors.append(CclError(tok.line, tok.col, message))

    def command(self, cmd: Command) -> None:
        period = self.period(cmd)
        if period is None:
            return
        first, last = period
        for d in cmd.definitions:
            self.guard(self.define, d, first)
        if not cmd.sets_view and cmd.time is None:
            return
        for p in (cmd.observer, cmd.viewpoint):
            if p is not None:
                self.guard(self.place, p, first, last)
        if cmd.focal is not None:
            self.set_focal(cmd.focal, first, last)
        self.owner[first - 1:last] = len(self.tokens)
        self.tokens.append(cmd.tok)
        self.periods.append((cmd.tok.line, first, last))
        self.prev_end = last

    def guard(self, fn, *args) -> None:
        try:
            fn(*args)
        except Unresolved as u:
            self.errors.append(u.error)

    # -- time ----------------------------------------------------------------------------
    def period(self, cmd: Command) -> tuple[int, int] | None:
        w, base = self.world, self.prev_end + 1
        if cmd.time is None:
            if not cmd.sets_view:  # definitions only: evaluated at `base`, no time taken
                return max(1, min(base, w.last)), max(1, min(base, w.last))
            return self.checked(cmd, base, w.last)
        try:
            first = w.event(cmd.time.start, base) if cmd.time.start else base
            last = w.event(cmd.time.until, first)
        except Unresolved as u:
            self.errors.append(u.error)
            return None
        return self.checked(cmd, first, last)

    def checked(self, cmd: Command, first: int, last: int) -> tuple[int, int] | None:
        t: Time | None = cmd.time
        at_start = t.start.tok if t and t.start else cmd.tok
        at_end = t.until.tok if t else cmd.tok
        n = self.world.last
        if first < 1:
            self.error(at_start, f"this command would start at frame {first}, before frame 1")
        elif first > n:
            self.error(at_start, f"this command would start at frame {first}, after the last "
                                 f"frame ({n})")
        elif last > n:
            self.error(at_end, f"this command would run until frame {last}, after the last "
                               f"frame ({n})")
        elif last < first:
            self.error(at_end, f"the period runs backwards: from frame {first} until frame "
                               f"{last}")
        else:
            return first, last
        return None

    # -- positions -----------------------------------------------------------------------
    def name(self, n: Name, frame: int) -> np.ndarray:
        w = self.world
        if n.kind == "ball":
            assert n.ball is not None
            return w.centre(w.ball(n.ball, frame), frame)
        if n.kind == "spot":
            return w.spots[n.key]
        if n.kind == "pocket":
            return w.pockets[n.key]
        return w.cameras[n.n]

    def coord(self, c: Coord, frame: int) -> np.ndarray:
        base = self.name(c.name, frame) if c.name is not None else None
        if c.simple is None:
            assert base is not None
            return base.copy()
        v = self.world.simple(c.simple, offset=base is not None)
        return v if base is None else base + c.sign * v

    def define(self, d: object, frame: int) -> None:
        w = self.world
        if isinstance(d, CoordsDef):
            w.origin = self.coord(d.origin, frame)
            w.factors = np.array(d.factors)
        else:
            w.cameras[d.n] = self.coord(d.at, frame)

    def place(self, p: Place, first: int, last: int) -> None:
        out = self.obs if p.what == "observer" else self.vp
        rows = slice(first - 1, last)
        if p.mode == "at":
            assert p.a is not None
            out[rows] = self.coord(p.a, first)
        elif p.mode == "moving":
            assert p.a is not None and p.b is not None
            a, b = self.coord(p.a, first), self.coord(p.b, first)
            out[rows] = a + _ramp(first, last)[:, None] * (b - a)
        else:
            assert p.ball is not None
            ball = self.world.ball(p.ball, first)
            off = np.zeros(3) if p.offset is None else p.sign * self.world.simple(p.offset, True)
            out[rows] = self.world.motion.centres[first - 1:last, ball] + off

    def set_focal(self, f: Focal, first: int, last: int) -> None:
        rows = slice(first - 1, last)
        self.focal[rows] = f.a if f.b is None else f.a + _ramp(first, last) * (f.b - f.a)

    # -- the result ----------------------------------------------------------------------
    def finish(self) -> Interpretation:
        obs = _fill(self.obs, space.ccl_to_table(names.DEFAULT_OBSERVER))
        vp = _fill(self.vp, np.array(names.DEFAULT_VIEWPOINT))
        focal = _fill(self.focal[:, None], np.array([names.DEFAULT_FOCAL_MM]))[:, 0]
        bad = np.flatnonzero(~np.all(np.isfinite(np.hstack([obs, vp])), axis=1))
        if bad.size:
            tok = self.tokens[int(self.owner[bad[0]])] or _Start
            self.error(tok, f"a position is too far away to compute at frame {bad[0] + 1} "
                            "(check the COORDS factors)")
            obs, vp = np.nan_to_num(obs), np.nan_to_num(vp)
        same = np.flatnonzero(np.all(obs == vp, axis=1))
        if same.size:
            f = int(same[0]) + 1
            tok = self.tokens[int(self.owner[f - 1])] or _Start
            count = f" (and {same.size - 1} more frames)" if same.size > 1 else ""
            self.error(tok, f"the observer and the viewpoint are the same point at frame {f}"
                            f"{count}: there is no direction to look in")
        lines = np.array([0 if t is None else t.line for t in self.tokens])
        return Interpretation(obs, vp, focal, lines[self.owner], self.periods,
                              sorted(self.errors))


class _Start:
    """Where an error about the start-of-day defaults is reported."""

    line = col = 1


def _ramp(first: int, last: int) -> np.ndarray:
    """0 at the first frame .. 1 at the last, linear in frame number (1 if one frame)."""
    if last == first:
        return np.ones(1)
    return (np.arange(first, last + 1, dtype=np.float64) - first) / (last - first)


def _fill(a: np.ndarray, default: np.ndarray) -> np.ndarray:
    """Forward-fill unset (NaN) rows; rows before the first set one take `default`."""
    set_ = ~np.isnan(a[:, 0])
    idx = np.where(set_, np.arange(a.shape[0]), -1)
    np.maximum.accumulate(idx, out=idx)
    out = np.where((idx >= 0)[:, None], a[np.maximum(idx, 0)], default[None, :])
    return out


def interpret(commands: list[Command], motion: Motion) -> Interpretation:
    run = _Run(motion)
    for cmd in commands:
        run.command(cmd)
    return run.finish()
