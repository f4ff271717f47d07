"""The interactive painting program (thesis §3.3): the animator's commands on one frame,
each answered with the Sigma orders that show its effect, and recorded in the operations
file as it goes.

Commands done in the painted frame are sequence operations (auto-paint repeats them in every
frame); done in any other frame they are that frame's own operations (touch-up).  *select*
highlights the chain nearest the cursor (highlight plane only); *fill* fills the closed
shape of the selected chains in the current colour and clears the highlights.
"""

from __future__ import annotations

from dataclasses import replace

from camlab88.apps.kas.model import AnimSequence
from camlab88.apps.kas.paint import areas, mixing, orders, outlines
from camlab88.apps.kas.paint.autopaint import Failure, Step
from camlab88.apps.kas.paint.ops import Op, OpsFile
from camlab88.apps.kas.paint.program import PaintProgram, nearest_chain

VIEWS = {"painting": areas.PAINTING.view, "mixing": areas.MIXING.view,
         "preview": areas.PREVIEW}


class PaintSession:
    def __init__(self, seq: AnimSequence, ops: OpsFile) -> None:
        if not seq.frames:
            raise ValueError("the sequence has no frames")
        self.program = PaintProgram(seq, ops)
        self.ops = ops
        self.n = ops.painted
        self.selected: list[int] = []
        self.view = VIEWS["painting"]
        self.failures: list[Failure] = []
        self.message = ""

    @property
    def seq(self) -> AnimSequence:
        return self.program.seq

    def start(self) -> bytes:
        p = self.program
        return p.setup() + self._repaint() + p.mixing_area() + p.show(self.view)

    def _repaint(self) -> bytes:
        data, plan = self.program.frame(self.n)
        self.failures = plan.failures
        return data

    # ------------------------------------------------------------ choosing
    def select_near(self, x: float, y: float) -> bytes:
        c = nearest_chain(self.seq, self.n, (x, y))
        if c in self.selected:
            return b""
        self.selected.append(c)
        self.message = f"selected line-chain {c}"
        return self.program.select(self.n, (c,))

    def clear(self) -> bytes:
        self.selected = []
        return self.program.clear_selection()

    # ------------------------------------------------------------ colouring
    def fill(self) -> bytes:
        return self._chains_op("fill")

    def colour_lines(self) -> bytes:
        return self._chains_op("line")

    def region(self, x: float, y: float) -> bytes:
        kind = "region" if self.n == self.ops.painted else "touch"
        return self._do(Op(kind, self.program.current, at=(x, y), frame=self._frame_tag()))

    def touch(self, x: float, y: float) -> bytes:
        return self._do(Op("touch", self.program.current, at=(x, y), frame=self.n))

    def _chains_op(self, kind: str) -> bytes:
        if not self.selected:
            self.message = f"{kind}: select line-chains first"
            return b""
        op = Op(kind, self.program.current, chains=tuple(self.selected),
                frame=self._frame_tag())
        self.selected = []
        return self._do(op)

    def _frame_tag(self) -> int | None:
        return None if self.n == self.ops.painted else self.n

    def _do(self, op: Op) -> bytes:
        """Plan the operation in this frame; record it only if it applies."""
        try:
            step = self.program.painter._step(op, self.n, self.seq.frames[self.n - 1])
        except (LookupError, ValueError) as exc:
            self.message = f"{op.kind}: {exc}"
            return self.program.clear_selection() if op.kind in ("fill", "line") else b""
        if op.kind == "fill":
            op = replace(op, seeds=tuple(areas.to_field(x, y) for x, y in step.seeds))
        if op.frame is None:
            self.ops.ops.append(op)
        else:
            self.ops.frame_ops.setdefault(self.n, []).append(op)
        self.message = f"{op.kind} in colour {op.colour}"
        return self._show_step(step)

    def _show_step(self, step: Step) -> bytes:
        p = self.program
        origin = areas.PAINTING.origin
        runs = outlines.runs(self.seq.frames[self.n - 1], p.outline)
        steps = p.plan(self.n).steps
        out = orders.step_bytes(p.enc, step, origin)
        return out + orders.outline_bytes(p.enc, runs, steps, origin) + p.clear_selection()

    # ------------------------------------------------------------ palette
    def pick(self, colour: int) -> bytes:
        self.ops.palette._index(colour)
        old, self.program.current = self.program.current, colour
        return mixing.frame_current(self.program.enc, colour, old) + self.program.editor()

    def rgb(self, gun: str, delta: int) -> bytes:
        self.ops.palette.step(self.program.current, gun, delta)
        return self._entry_changed()

    def mix(self, parts: dict[int, int]) -> bytes:
        self.ops.palette.mix(self.program.current, parts)
        return self._entry_changed()

    def _entry_changed(self) -> bytes:
        return self.program.palette_entry(self.program.current) + self.program.editor()

    # ------------------------------------------------------------ views and frames
    def show(self, which: str) -> bytes:
        if which not in VIEWS:
            raise ValueError(f"show painting, mixing or preview, not {which!r}")
        self.view = VIEWS[which]
        return self.program.show(self.view)

    def goto(self, n: int) -> bytes:
        if not 1 <= n <= len(self.seq.frames):
            raise ValueError(f"frame {n} outside 1..{len(self.seq.frames)}")
        self.n, self.selected = n, []
        return self._repaint()

    def autopaint(self) -> list[Failure]:
        """Plan every frame from the operations so far and record each frame's seeds in the
        operations file; the frames that could not take an operation."""
        plans, fails = self.program.painter.plan_all()
        self.program.painter.record(plans)
        return fails

    def area_point(self, sx: int, sy: int) -> tuple[float, float] | None:
        """A screen pixel (device units, y up) -> field inches in the painting area, or
        None if it is not on the painting area in the current view."""
        if self.view == areas.PREVIEW:
            ax, ay = sx * 2, sy * 2
        else:
            x0, y0 = areas.AREAS[[a.view for a in areas.AREAS].index(self.view)].origin
            ax, ay = sx + x0, sy + y0
        px0, py0, px1, py1 = areas.PAINTING.box()
        if not (px0 <= ax <= px1 and py0 <= ay <= py1):
            return None
        return areas.to_field(ax - px0, ay - py0)

    def swatch_at(self, sx: int, sy: int) -> int | None:
        """The palette entry whose swatch is under a screen pixel, if any."""
        step, (x0, y0) = (2, (0, 0)) if self.view == areas.PREVIEW else (1, (
            areas.AREAS[[a.view for a in areas.AREAS].index(self.view)].origin))
        ax, ay = x0 + sx * step, y0 + sy * step
        for i in range(len(self.ops.palette)):
            bx0, by0, bx1, by1 = mixing.swatch_box(i)
            if bx0 <= ax <= bx1 and by0 <= ay <= by1:
                return i
        return None
