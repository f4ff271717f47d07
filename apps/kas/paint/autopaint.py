"""Auto-paint (thesis §3.3): the operations done on one frame applied to every frame of the
sequence "by chain number, in the same order", with seed points recomputed for each frame's
own shapes -- unless the operations file already holds that frame's seeds ("seed point
coordinates, on a frame by frame basis"), which are then used, each checked to be inside;
``record`` writes the seeds every frame used back into the file.  A frame where an
operation cannot apply (a chain missing, a shape that no longer closes, a region not found,
a recorded seed outside) is listed with the operations file's line number, and everything
else is still painted.

A frame's plan is a list of steps in front-to-back order.  Each step draws its *walls* (the
boundary, in the highlight value 0x80 on all planes so that they are the only pixels of
that exact value), fills from each seed up to them, then draws its *cover* (what must take
the fill colour besides the filled pieces: the boundary itself for a select, gap-closing
segments for a region).  The Sigma orders are in ``orders``.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from camlab88.apps.kas.model import AnimSequence, Drawing
from camlab88.apps.kas.paint import areas, regions, seeds, shape
from camlab88.apps.kas.paint.ops import Op, OpsFile, Seeds, op_key


@dataclass
class Step:
    op: Op
    colour: int
    walls: list[np.ndarray] = field(default_factory=list)
    seeds: list[tuple[int, int]] = field(default_factory=list)
    cover: list[np.ndarray] = field(default_factory=list)
    clear: bool = False       # walls left at exactly 0x80: clear before the next step
    unline: list[np.ndarray] = field(default_factory=list)  # outlines to take away


@dataclass(frozen=True)
class Failure:
    frame: int
    line: int
    reason: str

    def __str__(self) -> str:
        where = f"line {self.line}" if self.line else "a session operation"
        return f"frame {self.frame}: operation at {where}: {self.reason}"


@dataclass
class FramePlan:
    frame: int                       # 1-based
    steps: list[Step]
    failures: list[Failure]


class AutoPainter:
    """Plans every frame of ``seq`` from ``ops``; regions are followed from the frame they
    were chosen in."""

    def __init__(self, seq: AnimSequence, ops: OpsFile) -> None:
        self.seq, self.ops = seq, ops
        self._arr: dict[int, regions.Arrangement] = {}
        self._sig: dict[int, tuple[set[tuple[int, int]], int]] = {}
        self._shapes: dict[tuple[int, tuple[int, ...]], tuple[np.ndarray, list]] = {}

    def arrangement(self, n: int) -> regions.Arrangement:
        if n not in self._arr:
            self._arr[n] = regions.arrangement(self.seq.frames[n - 1], self.ops.gap)
        return self._arr[n]

    def plan(self, n: int) -> FramePlan:
        frame = self.seq.frames[n - 1]
        steps, fails = [], []
        for i, op in enumerate(self.ops.ops_for(n)):
            try:
                step = self._step(op, n, frame)
                if i < len(self.ops.ops):
                    step = self._use_recorded(step, n, i)
                steps.append(step)
            except (shape.MissingChain, NoShape) as exc:
                fails.append(Failure(n, op.line_no, str(exc)))
        return FramePlan(n, steps, fails)

    def _use_recorded(self, step: Step, n: int, i: int) -> Step:
        """The seeds the operations file holds for this frame replace the computed ones
        (§3.3: seed points "on a frame by frame basis"), each checked to lie inside a closed
        piece of this frame's boundary, so an edited or stale seed can never leak."""
        op = step.op
        if op.kind not in ("fill", "region"):
            return step
        rec = self.ops.recorded_seeds(n, i)
        got, where = ((rec.seeds, rec.line_no) if rec is not None
                      else (op.seeds, op.line_no) if n == self.ops.painted and op.seeds
                      else (None, 0))
        if got is None:
            return step
        f = seeds.faces(step.walls)
        px = [tuple(int(v) for v in areas.to_px(np.array([p]))[0]) for p in got]
        for (x, y), p in zip(px, got, strict=True):
            k = f.label_at(x, y)
            if k <= 0 or not f.bounded[k]:
                raise NoShape(f"the seed ({p[0]:g}, {p[1]:g}) recorded at line {where} is not "
                              f"inside a closed piece of the shape")
        return replace(step, seeds=px)

    def _sequence(self, op: Op) -> bool:
        return any(op is o for o in self.ops.ops)

    def record(self, plans: list[FramePlan]) -> None:
        """Keep the seeds every sequence operation used in every frame (but the painted
        one, whose seeds are on the operation's own line) in the operations file."""
        # the painted frame last: it replaces operations, and the others match them by identity
        for p in sorted(plans, key=lambda p: p.frame == self.ops.painted):
            if p.frame == self.ops.painted:
                self._record_painted(p)
                continue
            recs = [Seeds(op_key(s.op), tuple(areas.to_field(x, y) for x, y in s.seeds))
                    for s in p.steps if s.op.kind in ("fill", "region") and self._sequence(s.op)]
            if recs:
                self.ops.frame_seeds[p.frame] = recs
            else:
                self.ops.frame_seeds.pop(p.frame, None)

    def plan_all(self) -> tuple[list[FramePlan], list[Failure]]:
        plans = [self.plan(n) for n in range(1, len(self.seq.frames) + 1)]
        return plans, [f for p in plans for f in p.failures]

    def _step(self, op: Op, n: int, frame: Drawing) -> Step:
        if op.kind == "fill":
            poly, found = self._shape(n, frame, op.chains)
            if not found:
                raise NoShape("the joined line-chains enclose no area")
            return Step(op, op.colour, [poly], found, [poly], clear=op.colour == 0)
        if op.kind == "line":
            lines = [areas.dedup(areas.to_px(_chain(frame, c).points)) for c in op.chains]
            return Step(op, op.colour, cover=lines, unline=lines)
        arr = self.arrangement(n)
        k = self._region(op, n, arr)
        return Step(op, op.colour, arr.walls + arr.gaps, [arr.faces.seed(k)], list(arr.gaps),
                    clear=True)

    def _shape(self, n: int, frame: Drawing,
               chains: tuple[int, ...]) -> tuple[np.ndarray, list[tuple[int, int]]]:
        """The closed shape of ``chains`` in frame ``n`` and its seeds, once per frame (an
        animator often fills the same chains again, in another colour or order)."""
        key = (n, chains)
        if key not in self._shapes:
            poly = areas.dedup(areas.to_px(shape.closed_shape(frame, chains)))
            self._shapes = {k: v for k, v in self._shapes.items() if k[0] == n}
            self._shapes[key] = poly, seeds.shape_seeds(poly)
        poly, found = self._shapes[key]
        return poly, list(found)

    def _region(self, op: Op, n: int, arr: regions.Arrangement) -> int:
        assert op.at is not None
        if op.kind == "touch":
            px = areas.to_px(np.array([op.at]))[0]
            k = arr.faces.label_at(int(px[0]), int(px[1]))
            if k <= 0 or not arr.faces.bounded[k]:
                raise NoShape("the point is on a line or outside every closed region")
            return k
        src_n = op.frame or self.ops.painted
        key = id(op)
        if key not in self._sig:
            src = self.arrangement(src_n)
            k0 = regions.face_at(src, op.at)
            if not k0:
                self._sig[key] = (set(), 0)
            else:
                self._sig[key] = (regions.signature(src, k0), k0)
        sig, k0 = self._sig[key]
        if not k0:
            raise NoShape(f"the point is on a line or outside every closed region of frame "
                          f"{src_n}")
        k = k0 if n == src_n else regions.follow(sig, op.at, self.arrangement(src_n), arr)
        if not k:
            raise NoShape("the region was not found in this frame")
        return k


    def _record_painted(self, p: FramePlan) -> None:
        for s in p.steps:
            if s.op.kind == "fill" and not s.op.seeds and self._sequence(s.op):
                i = next(i for i, o in enumerate(self.ops.ops) if o is s.op)
                self.ops.ops[i] = replace(s.op, seeds=tuple(areas.to_field(x, y)
                                                            for x, y in s.seeds))


class NoShape(ValueError):
    """An operation that cannot apply to a frame."""


def _chain(frame: Drawing, c: int):
    if not 1 <= c <= len(frame.chains):
        raise shape.MissingChain(f"line-chain {c} is missing (the frame has "
                                 f"{len(frame.chains)})")
    return frame.chains[c - 1]
