"""Shared helpers for the painting tests: a T5688 set up for painting, and sequences."""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas import files
from camlab88.apps.kas.inbetween import inbetween
from camlab88.apps.kas.library import LIBRARY
from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from camlab88.apps.kas.paint.ops import Op, OpsFile
from camlab88.apps.kas.paint.program import Line, PaintProgram
from camlab88.emulator.harness.sigma_batch import link
from camlab88.emulator.sigma import Terminal

# the walk's body (line-chain 2) filled in colour 3, its head (line-chain 1) in colour 5
WALK_FILLS = (Op("fill", 3, chains=(2,)), Op("fill", 5, chains=(1,)))


def terminal_for(program: PaintProgram) -> Terminal:
    t = Terminal("t5688")
    t.feed(program.setup())
    return t


def t5688_line() -> tuple[Line, Terminal]:
    """The painting program's line to a fresh T5688 (no XON/XOFF: the orders are binary), and
    the terminal at its far end."""
    paint = link("t5688", xonxoff=False)
    return Line(paint), paint.machine.terminal


def one_frame(*chains: np.ndarray) -> AnimSequence:
    return AnimSequence([Drawing([Chain.from_points(c, 1) for c in chains])])


def walk(frames: int = 20) -> AnimSequence:
    """The shipped walk, made with the in-betweener (path, no ticks: any frame count)."""
    return inbetween(files.load_keyframe(LIBRARY / "walk_a.kas"),
                     files.load_keyframe(LIBRARY / "walk_b.kas"),
                     path=files.load_path(LIBRARY / "walk_path.kas"), frames=frames)


def sun(frames: int = 20) -> AnimSequence:
    return inbetween(files.load_keyframe(LIBRARY / "sun_a.kas"),
                     files.load_keyframe(LIBRARY / "sun_b.kas"),
                     timing=files.load_timing(LIBRARY / "ease-in-out.kas"), frames=frames)


def program(seq: AnimSequence, ops: OpsFile) -> PaintProgram:
    return PaintProgram(seq, ops)
