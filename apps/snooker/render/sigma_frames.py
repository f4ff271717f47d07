"""The Sigma modes' frames as files: one frame on a fresh T5688 as PNG bytes (``SigmaFrames``,
a picklable renderer for the film scheduler's workers), a whole sequence on one T5688 staged
so nothing is half-written (``render_staged``), and the resume record of frames so drawn
(``record``)."""

from __future__ import annotations

import hashlib
import os
import shutil
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from camlab88.protocols.link.port import BatchLink

LinkFactory = Callable[[], BatchLink]


@dataclass(frozen=True)
class SigmaFrames:
    """One frame on a fresh emulated T5688 (set up, LUT loaded, the frame's orders over the
    9600-baud line, the screen read back) -> PNG bytes: a picklable renderer for the film
    scheduler's workers (``link`` must be picklable: a module-level function). Byte-identical
    to one terminal drawing frame after frame, because every frame starts from a cleared
    screen (checked in tests/snooker_render/test_parallel.py)."""

    mode: str
    specks: bool
    palette_sha: str
    palette: object = field(repr=False, compare=False)
    link: LinkFactory | None = field(default=None, repr=False, compare=False)

    def __call__(self, scene, task) -> bytes:
        from camlab88.apps.snooker.render.sequence import render_sequence
        from camlab88.base.png import png_bytes

        f = next(render_sequence(scene, [task.view], self.mode, (768, 512), self.palette,
                                 self.link, self.specks))
        return png_bytes(f.image)


def sigma_frames(mode: str, specks: bool, palette, link: LinkFactory) -> SigmaFrames:
    lut = np.ascontiguousarray(palette.linear, dtype=np.float64).tobytes()
    return SigmaFrames(mode, specks, hashlib.sha256(lut).hexdigest()[:32], palette, link)


@dataclass
class LineTotals:
    """What the line carried for a sequence: seconds, leaking pixels, gaps."""

    line: float = 0.0
    leaks: float = 0.0
    gaps: float = 0.0


def render_staged(scene, views: Sequence, out: Path, mode: str, size: tuple[int, int],
                  palette, link: LinkFactory, specks: bool = True, wood: bool = True,
                  show: Callable[[int, int], None] | None = None) -> LineTotals:
    """Every view on one T5688, frame after frame; each PNG goes to a staging directory in
    ``out`` first and all are moved into place at the end (nothing half-written)."""
    from camlab88.apps.snooker.render.sequence import render_sequence
    from camlab88.base.png import frame_path, write_png

    out.mkdir(exist_ok=True)  # one level: its parent was checked (the one output rule)
    stage = Path(tempfile.mkdtemp(prefix=".render-", dir=out))
    totals = LineTotals()
    try:
        for k, f in enumerate(render_sequence(scene, views, mode, size, palette, link,
                                              specks, wood), start=1):
            write_png(f.image, frame_path(stage, f.frame))
            totals.line += f.line_seconds or 0.0
            totals.leaks += f.leaks or 0
            totals.gaps += f.gaps or 0
            if show is not None:
                show(k, len(views))
        for f in sorted(stage.iterdir()):
            os.replace(f, out / f.name)
    finally:
        shutil.rmtree(stage, ignore_errors=True)
    return totals


def record(scene, views: Sequence, out: Path, render: SigmaFrames, name: str) -> None:
    """The frames just drawn, in the resume record ``out/name`` (a parallel rerun skips
    them)."""
    from camlab88.apps.snooker.film.pipeline import FilmLook, film_digest
    from camlab88.apps.snooker.film.schedule import Manifest, frame_file
    from camlab88.apps.snooker.film.task import task_key

    look = FilmLook(specks=render.specks)
    manifest, digest = Manifest(out / name), film_digest(scene, render)
    for v in views:
        png = frame_file(out, int(v.frame)).read_bytes()  # what was just moved into place
        manifest.put(int(v.frame), task_key(digest, look.task(v)), png)
    manifest.save()
