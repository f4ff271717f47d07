"""The in-betweener's interactive part as a model (§3.1.2): drawing the sample path and
placing timing tick marks, driven by the same abstract events as the keyframe editor.

Both keyframes are shown superimposed in different colours (and the previous pair's path,
from the library, to help continuity); the animator draws a path with the stylus down
between any two points (or anywhere), then presses ``t`` and touches tick marks along it,
one per in-between frame.  ``u`` undoes the last tick (or, with none, clears the path);
``c`` clears everything.  The result is a ``SamplePath`` and a tick ``Timing``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from camlab88.apps.kas.events import Event, Key, Pointer
from camlab88.apps.kas.files import SamplePath, Timing
from camlab88.apps.kas.model import Drawing

STEP = 0.03  # inches between freehand path points


@dataclass
class PathEditor:
    first: Drawing
    second: Drawing
    previous_path: SamplePath | None = None
    path: list[tuple[float, float]] = field(default_factory=list)
    ticks: list[float] = field(default_factory=list)  # fractions of the path length
    mode: str = "path"  # path | ticks
    message: str = ""
    _down: bool = False

    def feed(self, ev: Event) -> None:
        if isinstance(ev, Pointer):
            touch = ev.down and not self._down
            drag = ev.down and self._down
            self._down = ev.down
            p = (ev.x, ev.y)
            if self.mode == "path":
                if touch and self.path:
                    self.message = "a path is drawn in one stroke: clear it (c) to redraw"
                elif touch or (drag and self.path and math.dist(self.path[-1], p) >= STEP):
                    self.path.append(p)
            elif touch:
                self.ticks.append(self.nearest_fraction(p))
        elif isinstance(ev, Key):
            k = ev.key.lower()
            if k == "t":
                if len(self.path) < 2 or self.sample_path() is None:
                    self.message = "draw the path first"
                else:
                    self.mode = "ticks"
            elif k == "p":
                self.mode = "path"
            elif k == "u":
                if self.ticks:
                    self.ticks.pop()
                else:
                    self.path.clear()
                    self.mode = "path"
            elif k == "c":
                self.path.clear()
                self.ticks.clear()
                self.mode = "path"
            else:
                self.message = f"no command {ev.key!r}"

    def run(self, events: list[Event]) -> None:
        for ev in events:
            self.feed(ev)

    def sample_path(self) -> SamplePath | None:
        pts = np.array(self.path, dtype=np.float64).reshape(-1, 2)
        if len(pts) < 2 or np.hypot(*np.diff(pts, axis=0).T).sum() == 0:
            return None
        return SamplePath(pts)

    def nearest_fraction(self, p: tuple[float, float]) -> float:
        """Fraction of the path length at the point of the path nearest ``p``."""
        pts = np.array(self.path, dtype=np.float64)
        a, b = pts[:-1], pts[1:]
        d = b - a
        seg = np.hypot(d[:, 0], d[:, 1])
        with np.errstate(invalid="ignore", divide="ignore"):
            t = np.clip(((np.asarray(p) - a) * d).sum(1) / (seg * seg), 0, 1)
        t = np.nan_to_num(t)
        foot = a + t[:, None] * d
        i = int(np.argmin(np.hypot(*(foot - p).T)))
        cum = np.concatenate([[0.0], np.cumsum(seg)])
        return float((cum[i] + t[i] * seg[i]) / cum[-1])

    def timing(self) -> Timing:
        """The ticks in order along the path, whatever order they were touched in (each
        tick is one in-between; the frames follow the path)."""
        return Timing("ticks", sorted(self.ticks), "hand ticks")

    def tick_points(self) -> np.ndarray:
        from camlab88.apps.kas.pathfit import point_at

        sp = self.sample_path()
        if sp is None or not self.ticks:
            return np.zeros((0, 2))
        return point_at(sp, np.array(self.ticks))

    def display_list(self) -> list[tuple[str, np.ndarray, int]]:
        """(role, points, colour): first/second keyframe chains in two colours, the previous
        path, the path, the ticks."""
        out = [("first", c.points, 6) for c in self.first.chains]
        out += [("second", c.points, 7) for c in self.second.chains]
        if self.previous_path is not None:
            out.append(("previous-path", self.previous_path.points, 4))
        if self.path:
            out.append(("path", np.array(self.path), 5))
        out += [("tick", p[None], 1) for p in self.tick_points()]
        return out
