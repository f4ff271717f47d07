"""Shared helpers for the painting tests: a T5688 set up for painting, and sequences."""

from __future__ import annotations

import numpy as np

from apps.kas import files
from apps.kas.inbetween import inbetween
from apps.kas.library import LIBRARY
from apps.kas.model import AnimSequence, Chain, Drawing
from apps.kas.paint.ops import OpsFile
from apps.kas.paint.program import PaintProgram
from emulator.sigma import Terminal


def terminal_for(program: PaintProgram) -> Terminal:
    t = Terminal("t5688")
    t.feed(program.setup())
    return t


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
