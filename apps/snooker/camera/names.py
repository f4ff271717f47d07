"""What CCL's names mean at a given frame (thesis §6.3.1): balls (RED <n> and HITBALL
included), spots, pockets, the ten cameras, the user's coordinate space, and the frames of
the events a script can wait for.  Frames are numbered from 1 (motion.py)."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.camera import space
from camlab88.apps.snooker.camera.errors import CclError
from camlab88.apps.snooker.camera.motion import Motion
from camlab88.apps.snooker.camera.syntax import BallRef, Event, Simple
from camlab88.apps.snooker.table import CUE, REDS

# Cameras at the start of day, in CCL's default space (+x towards the baulk cushion:
# space.py).  Reconstructed: the thesis names "the default position of camera 1" as "a
# general view showing the whole table" and gives no other values.  0: straight above the
# table's centre; 1-8: a ring 2.5 m up round the table, anticlockwise seen from above from
# the baulk end (1) by way of the right side (3) and the top end (5); 9: a player's eye
# behind the baulk cushion.
_C, _S, _Z = 3.889087, 3.181981, 2.5  # 5.5 cos 45 and 4.5 sin 45 (m): the ring's diagonals
DEFAULT_CAMERAS: dict[int, tuple[float, float, float]] = {
    0: (0.0, 0.0, 8.0),
    1: (5.5, 0.0, _Z), 2: (_C, -_S, _Z), 3: (0.0, -4.5, _Z), 4: (-_C, -_S, _Z),
    5: (-5.5, 0.0, _Z), 6: (-_C, _S, _Z), 7: (0.0, 4.5, _Z), 8: (_C, _S, _Z),
    9: (2.6, 0.0, 1.2),
}
DEFAULT_OBSERVER = DEFAULT_CAMERAS[1]
DEFAULT_VIEWPOINT = (0.0, 0.0, 0.0)
DEFAULT_FOCAL_MM = 50.0


class Unresolved(Exception):
    """A name or event that has no meaning in this motion (an error at its token)."""

    def __init__(self, error: CclError) -> None:
        self.error = error


def _fail(tok: object, message: str) -> Unresolved:
    return Unresolved(CclError(tok.line, tok.col, message))


class World:
    """Names and events over one motion, plus the script's cameras and user space, all held
    in the table frame (literal coordinates are mirrored in from CCL's space: ``simple``)."""

    def __init__(self, motion: Motion) -> None:
        self.motion = motion
        self.cameras = {n: space.ccl_to_table(v) for n, v in DEFAULT_CAMERAS.items()}
        self.origin = np.zeros(3)
        self.factors = np.ones(3)
        self.spots = space.spots(motion.table)
        self.pockets = space.pockets(motion.table)
        moved = motion.moved
        self.starts = moved[1:-1] & ~moved[:-2]  # row f-1 is frame f
        self.stops = moved[1:-1] & ~moved[2:]
        anyb = moved.any(axis=1)
        self.any_starts = self.starts.any(axis=1)
        self.all_stop = anyb[1:-1] & ~anyb[2:]

    @property
    def last(self) -> int:
        return self.motion.n_frames

    # -- balls ---------------------------------------------------------------------------
    def ball(self, b: BallRef, frame: int) -> int:
        if b.kind == "cue":
            return CUE
        if b.kind == "colour":
            return space.COLOUR_BALLS[b.colour]
        if b.kind == "red":
            return self._red(b, frame)
        return self._hit(b, frame)

    def _red(self, b: BallRef, frame: int) -> int:
        """The n-th red nearest the top cushion at `frame`; equal distances counted left
        to right as seen from the baulk end (+y first)."""
        on = [r for r in REDS if self.motion.on_table[frame - 1, r]]
        c = self.motion.centres[frame - 1]
        on.sort(key=lambda r: (-c[r, 0], -c[r, 1]))
        if b.n > len(on):
            raise _fail(b.tok, f"there {'is' if len(on) == 1 else 'are'} only {len(on)} "
                               f"red{'' if len(on) == 1 else 's'} on the table at frame {frame}, "
                               f"so there is no red {b.n}")
        return on[b.n - 1]

    def _hit(self, b: BallRef, frame: int) -> int:
        """The ball the cue ball struck most recently at or before `frame`, else the first
        one it strikes after it."""
        strikes = self.motion.strikes
        if not strikes:
            raise _fail(b.tok, "the cue ball never strikes another ball, so there is no HITBALL")
        before = [ball for f, ball in strikes if f <= frame]
        return before[-1] if before else strikes[0][1]

    def centre(self, ball: int, frame: int) -> np.ndarray:
        return self.motion.centres[frame - 1, ball]

    # -- coordinates ---------------------------------------------------------------------
    def simple(self, s: Simple, offset: bool) -> np.ndarray:
        """A simple coordinate (CCL's space, or the user's) as a table-frame position (or,
        after a name's +/-, a displacement)."""
        v = np.array(s.xyz, dtype=np.float64)
        if not s.user:
            return space.ccl_to_table(v)
        d = space.ccl_to_table(v / self.factors)
        return d if offset else self.origin + d

    # -- events --------------------------------------------------------------------------
    def event(self, e: Event, after: int) -> int:
        """The frame of `e`'s first occurrence at or after frame `after`, plus its offset."""
        return self._occurrence(e, after) + e.offset

    def _occurrence(self, e: Event, after: int) -> int:
        if e.kind == "frame":
            return e.frame
        if e.kind == "end":
            return self.last
        if e.kind == "strike":
            for f, _ in self.motion.strikes:
                if f >= after:
                    return f
            raise _fail(e.tok, f"the cue ball never strikes another ball at or after frame "
                               f"{after}")
        if e.kind in ("any_start", "all_stop"):
            rows = self.any_starts if e.kind == "any_start" else self.all_stop
            what = "no ball starts" if e.kind == "any_start" else "the balls never all stop"
            return self._first(rows, after, e, f"{what} at or after frame {after}")
        assert e.ball is not None
        b = self.ball(e.ball, max(1, min(after, self.last)))
        rows = (self.starts if e.kind == "start" else self.stops)[:, b]
        verb = "starts" if e.kind == "start" else "stops"
        return self._first(rows, after, e, f"{e.ball.describe()} never {verb} at or after "
                                           f"frame {after}")

    def _first(self, rows: np.ndarray, after: int, e: Event, message: str) -> int:
        hits = np.flatnonzero(rows[max(after, 1) - 1:])
        if hits.size == 0:
            raise _fail(e.tok, message)
        return int(hits[0]) + max(after, 1)
