"""Auto-paint (thesis §3.3): the operations done on one frame applied to every frame of the
sequence "by chain number, in the same order", with seed points recomputed for each frame's
own shapes.  A frame where an operation cannot apply (a chain missing, a shape that no
longer closes, a region not found) is listed with the operations file's line number, and
everything else is still painted.

A frame's plan is a list of steps in front-to-back order.  Each step draws its *walls* (the
boundary, in the highlight value 0x80 on all planes so that they are the only pixels of
that exact value), fills from each seed up to them, then draws its *cover* (what must take
the fill colour besides the filled pieces: the boundary itself for a select, gap-closing
segments for a region).  The Sigma orders are in ``orders``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from apps.kas.model import AnimSequence, Drawing
from apps.kas.paint import areas, regions, seeds, shape
from apps.kas.paint.ops import Op, OpsFile


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

    def arrangement(self, n: int) -> regions.Arrangement:
        if n not in self._arr:
            self._arr[n] = regions.arrangement(self.seq.frames[n - 1], self.ops.gap)
        return self._arr[n]

    def plan(self, n: int) -> FramePlan:
        frame = self.seq.frames[n - 1]
        steps, fails = [], []
        for op in self.ops.ops_for(n):
            try:
                steps.append(self._step(op, n, frame))
            except (shape.MissingChain, NoShape) as exc:
                fails.append(Failure(n, op.line_no, str(exc)))
        return FramePlan(n, steps, fails)

    def plan_all(self) -> tuple[list[FramePlan], list[Failure]]:
        plans = [self.plan(n) for n in range(1, len(self.seq.frames) + 1)]
        return plans, [f for p in plans for f in p.failures]

    def _step(self, op: Op, n: int, frame: Drawing) -> Step:
        if op.kind == "fill":
            poly = areas.dedup(areas.to_px(shape.closed_shape(frame, op.chains)))
            found = seeds.shape_seeds(poly)
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


class NoShape(ValueError):
    """An operation that cannot apply to a frame."""


def _chain(frame: Drawing, c: int):  # noqa: ANN202
    if not 1 <= c <= len(frame.chains):
        raise shape.MissingChain(f"line-chain {c} is missing (the frame has "
                                 f"{len(frame.chains)})")
    return frame.chains[c - 1]
