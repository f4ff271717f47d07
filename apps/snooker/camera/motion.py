"""The balls' motion as CCL sees it: every frame's ball centres in the default space, which
balls are on the table, and the events a script can name (thesis §6.3.1).

Frames: a checkpoint's 22 initial positions are frame 1 and its k-th delta line frame k+1;
a session's time frame n is frame n+1.  moved(f) means a ball's position at f differs from
f-1 (never at frame 1, nor after the last frame); ``<ball> STARTS`` is a frame with moved(f)
and not moved(f-1), ``<ball> STOPS`` one with moved(f) and not moved(f+1); ANY BALL STARTS
is any ball's STARTS, ALL BALLS STOP a frame where some ball moved and none moves in the
next.  A potted ball's jump behind its pocket counts as movement.

Strikes of the cue ball: from a session file, its ball-ball collision events (a collision
at time t in ((n-1)/rate, n/rate] shows first in time frame n).  From a checkpoint they are
inferred: frame f is a strike of ball b when b's displacement over the frame changes by more
than KICK_M from the frame before (it was pushed) and the cue ball came within touching
distance of it during the frame: both going on from f-1 as they moved into it, their
centres come within a diameter plus CONTACT_TOL_M, or, both moving in a straight line from
f-1 to f, within a diameter plus CONTACT_SLACK (of the distances the two moved, since the
real paths bend at the contact) plus CONTACT_TOL_M.  A contact seen in two frames is one
strike; of several balls pushed in one frame, the one reached first (going on as before, if
any) is the one struck.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from camlab88.apps.snooker import checkpoint as cpfile
from camlab88.apps.snooker.camera import space
from camlab88.apps.snooker.events import EventKind
from camlab88.apps.snooker.table import CUE, Table

KICK_M = 1e-3  # a change of displacement per frame above this (0.025 m/s at 25/s) is a push
CONTACT_SLACK = 0.25
CONTACT_TOL_M = 2e-3


@dataclass(frozen=True, eq=False)
class Motion:
    table: Table
    centres: np.ndarray  # (F, 22, 3) default-space ball centres; index 0 is frame 1
    on_table: np.ndarray  # (F, 22) bool
    strikes: tuple[tuple[int, int], ...]  # (frame, ball) the cue ball struck, in order

    @property
    def n_frames(self) -> int:
        return int(self.centres.shape[0])

    @property
    def moved(self) -> np.ndarray:
        """(F + 2, 22) bool, row f is frame f (rows 0 and F + 1 are all False)."""
        return _moved(self.centres)


def _moved(c: np.ndarray) -> np.ndarray:
    out = np.zeros((c.shape[0] + 2, c.shape[1]), dtype=bool)
    out[2:-1] = np.any(c[1:] != c[:-1], axis=2)
    return out


def from_checkpoint(cp: cpfile.Checkpoint, table: Table | None = None) -> Motion:
    table = table or Table()
    centres, on = space.checkpoint_centres(cp, table)
    return Motion(table, centres, on, infer_strikes(centres, on, table.radius))


def infer_strikes(c: np.ndarray, on: np.ndarray, r: float) -> tuple[tuple[int, int], ...]:
    d = np.zeros_like(c[:, :, :2])
    d[1:] = c[1:, :, :2] - c[:-1, :, :2]  # displacement into each frame
    kick = np.zeros(on.shape, dtype=bool)
    kick[1:] = np.linalg.norm(d[1:] - d[:-1], axis=2) > KICK_M
    rel0 = c[:-1, :, :2] - c[:-1, CUE:CUE + 1, :2]  # relative to the cue ball, at f-1
    chord = (c[1:, :, :2] - c[1:, CUE:CUE + 1, :2]) - rel0  # as both moved into f
    ahead = d[:-1] - d[:-1, CUE:CUE + 1]  # as both would have moved, going on as before
    travel = np.linalg.norm(d[1:], axis=2)
    reach = 2 * r + CONTACT_SLACK * (travel + travel[:, CUE:CUE + 1]) + CONTACT_TOL_M
    straight = _contact_time(rel0, ahead, np.full_like(reach, 2 * r + CONTACT_TOL_M))
    # the paths going on as before are straight up to the contact: rank by them first
    t = np.where(np.isfinite(straight), straight, 1.0 + _contact_time(rel0, chord, reach))
    hit = kick[1:] & np.isfinite(t) & on[:-1] & on[:-1, CUE:CUE + 1]  # t in [0, 2]
    hit[:, CUE] = False
    hit[1:] &= ~hit[:-1]  # one contact seen over two frames is one strike
    # one strike a frame: the pushed ball reached first (a ball the struck ball pushes on
    # in the same frame may be within reach too)
    frames = np.flatnonzero(hit.any(axis=1))
    balls = np.argmin(np.where(hit[frames], t[frames], np.inf), axis=1)
    return tuple((int(f) + 2, int(b)) for f, b in zip(frames, balls))


def _contact_time(p0: np.ndarray, step: np.ndarray, reach: np.ndarray) -> np.ndarray:
    """First t in [0, 1] with |p0 + t step| <= reach (inf if none), over (frames, balls)."""
    a = np.einsum("fbk,fbk->fb", step, step)
    b = 2.0 * np.einsum("fbk,fbk->fb", p0, step)
    cc = np.einsum("fbk,fbk->fb", p0, p0) - reach * reach
    disc = b * b - 4.0 * a * cc
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (-b - np.sqrt(np.maximum(disc, 0.0))) / (2.0 * a)
    t = np.where((disc >= 0.0) & (a > 0.0) & (t >= 0.0) & (t <= 1.0), t, np.inf)
    return np.where(cc <= 0.0, 0.0, t)


def from_session(session: object) -> Motion:
    """A motion-development session (apps.snooker.session.Session): the positions its
    checkpoint would hold (so both files give the same frames) and its collision events."""
    tl = session.timeline
    table = tl.table
    centres, on = space.checkpoint_centres(session.checkpoint(), table)
    strikes = []
    for f in tl.event_frames:
        e = f.event
        if e is None or e.kind != EventKind.BALL_BALL or CUE not in (e.a, e.b):
            continue
        frame = f.index + 2  # after time frame k, first seen in time frame k + 1
        if frame <= len(tl.time_frames):
            strikes.append((frame, e.b if e.a == CUE else e.a))
    return Motion(table, centres, on, tuple(sorted(strikes)))


def load(path: str | os.PathLike[str]) -> Motion:
    """A checkpoint file or a session file (JSON), told apart by the first character."""
    head = Path(path).read_bytes()[:256].lstrip() if Path(path).is_file() else b""
    if head.startswith(b"{"):
        from camlab88.apps.snooker.session import Session

        return from_session(Session.load(path))
    return from_checkpoint(cpfile.read(path))


def timeline_events(m: Motion) -> list[tuple[int, str, int]]:
    """(frame, "strike" | "start" | "stop", ball) for every event a script can name, in
    frame order (strikes name the ball struck)."""
    moved = m.moved
    starts = moved[1:-1] & ~moved[:-2]
    stops = moved[1:-1] & ~moved[2:]
    out = [(f, "strike", b) for f, b in m.strikes]
    for kind, rows in (("start", starts), ("stop", stops)):
        frames, balls = np.nonzero(rows)
        out += [(int(f) + 1, kind, int(b)) for f, b in zip(frames, balls)]
    return sorted(out)
