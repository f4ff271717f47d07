"""Replay of a painted sequence, double-buffered in the two spare quarters of the drawing
area (thesis §3.3: "double buffering (using the remaining two unused quarters of the
terminal's drawing area) means that the animator is never presented with a partly-drawn
picture"), and export of the frames as PNG / GIF / MP4 like ``kas export``.

Each frame is painted into the hidden buffer; only when its last order has arrived is the
view switched to it (one ``KQ`` order, instantaneous).  The caller's ``on_shown(n, line
time)`` sees the screen at that moment, e.g. to take the frame for export.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from camlab88.apps.kas.paint.areas import BUFFERS
from camlab88.apps.kas.paint.autopaint import Failure
from camlab88.apps.kas.paint.program import Line, PaintProgram
from camlab88.base.atomicfile import write_atomic
from camlab88.protocols.link.port import HostPort


@dataclass
class ReplayReport:
    frames: int = 0
    setup_time: float = 0.0
    frame_times: list[float] = field(default_factory=list)  # line seconds per frame
    chars: list[int] = field(default_factory=list)
    failures: list[Failure] = field(default_factory=list)

    def summary(self) -> str:
        t = np.array(self.frame_times) if self.frame_times else np.zeros(1)
        return (f"{self.frames} frames painted over the line: {sum(self.chars)} characters, "
                f"{t.sum():.1f} s of line time ({t.mean():.2f} s a frame, at most "
                f"{t.max():.2f} s); set-up {self.setup_time:.2f} s; "
                f"{len(self.failures)} operation(s) could not apply")


def replay(program: PaintProgram, line: Line,
           on_shown: Callable[[int, float], None] | None = None,
           frames: range | None = None) -> ReplayReport:
    rep = ReplayReport()
    t0 = line.now
    rep.setup_time = line.send(program.setup()) - t0
    for k, n in enumerate(frames or range(1, len(program.seq.frames) + 1)):
        buf = BUFFERS[k % 2]
        start = line.now
        data, plan = program.frame(n, buf)
        data += program.show(buf.view)
        shown = line.send(data)
        rep.frames += 1
        rep.frame_times.append(shown - start)
        rep.chars.append(len(data))
        rep.failures += plan.failures
        if on_shown is not None:
            on_shown(n, shown)
    return rep


def write_frames(images: list[np.ndarray], out_dir: str | os.PathLike[str]) -> list[Path]:
    """frame_00001.png ... (numbered from 1), each written atomically."""
    import imageio.v3 as iio

    d = Path(out_dir)
    d.mkdir(parents=True, exist_ok=True)
    paths = []
    for i, img in enumerate(images, start=1):
        p = d / f"frame_{i:05d}.png"
        write_atomic(p, iio.imwrite("<bytes>", img, extension=".png"))
        paths.append(p)
    return paths


def write_movie(images: list[np.ndarray], out: str | os.PathLike[str], fps: float) -> Path:
    """A GIF or MP4 of the frames (MP4 through imageio-ffmpeg), written atomically."""
    from camlab88.apps.kas.export import export
    from camlab88.apps.kas.model import AnimSequence, Drawing

    frames = [Drawing() for _ in images]
    by_id = {id(f): img for f, img in zip(frames, images, strict=True)}
    return export(AnimSequence(frames, fps), out, render_frame=lambda f: by_id[id(f)])


class ReplayHost:
    """The replay as a host program on its port, one step at a time, for a machine run
    period by period (the demo) or frame by frame (``kas paint --replay``): the set-up and
    the first frame go at once; each ``step`` writes the next frame, double-buffered, once
    the line has delivered the last one."""

    def __init__(self, program: PaintProgram, port: HostPort,
                 frames: range | None = None) -> None:
        self.program, self.port = program, port
        self.frames = list(frames or range(1, len(program.seq.frames) + 1))
        self.shown = 0  # frames written
        self.chars = 0  # characters of the frames' orders
        self.failures: list[Failure] = []
        self.plans: list = []
        port.write(program.setup())
        if self.frames:
            self._write_next()

    @property
    def finished(self) -> bool:
        return self.shown == len(self.frames)

    def step(self) -> bool:
        """Write the next frame if the line is quiet; False when none was written."""
        if self.finished or not self.port.drained():
            return False
        self._write_next()
        return True

    def _write_next(self) -> None:
        buf = BUFFERS[self.shown % 2]
        data, plan = self.program.frame(self.frames[self.shown], buf)
        self.port.write(data + self.program.show(buf.view))
        self.shown += 1
        self.chars += len(data)
        self.failures += plan.failures
        self.plans.append(plan)
