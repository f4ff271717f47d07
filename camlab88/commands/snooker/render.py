"""``camlab88 snooker render CHECKPOINT|SESSION VIEWS --frames DIR``: finished frames
(thesis 6.4, 6.4.1) — ``period`` and ``fixed`` on the emulated Sigma T5688 over the
9600-baud line, ``truecolour`` in 24-bit at any size; frame_NNNNN.png numbered as the
checkpoint's frames (from 1). Truecolour frames render in parallel and resume through
apps.snooker.film's scheduler (a local pool, or ``--dask ADDRESS|local``); the Sigma modes
draw on one emulated T5688, frame after frame."""

from __future__ import annotations

import argparse
import os
import shutil
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from camlab88.runopts import fail, frames_dir, positive, progress

COMMAND = "camlab88 snooker render"
RECORD = ".camlab88-render.json"  # the resume record, hidden among the frames


def _size(text: str) -> tuple[int, int]:
    w, sep, h = text.lower().partition("x")
    if not (sep and w.isascii() and w.isdigit() and h.isascii() and h.isdigit()):
        raise argparse.ArgumentTypeError(f"expected WxH such as 768x512, not {text!r}")
    if not (8 <= int(w) <= 8192 and 8 <= int(h) <= 8192):
        raise argparse.ArgumentTypeError(f"{text}: each side must be 8..8192 pixels")
    return int(w), int(h)


DESCRIPTION = (
    "Render every frame of a view file over a checkpoint or session. "
    "--mode period: the 1984 program on the emulated T5688 over the 9600-baud line "
    "(firmware outlines + flood fill: polygon colour leaks past the anti-aliased edges, "
    "counted); fixed: the same with software Bresenham outlines (no leaks); adapted: "
    "firmware outlines anti-aliased where the firmware puts them (no leaks, period's line "
    "time); truecolour: 24-bit at --size. Writes DIR/frame_NNNNN.png numbered as the "
    "checkpoint's frames. Truecolour renders in parallel: one process per core (--workers N), "
    "or on a Dask cluster (--dask tcp://HOST:8786 from 'dask scheduler' + 'dask worker', "
    "or --dask local); it resumes: a frame whose PNG is complete and was made from the "
    "same shot, view and settings (DIR/.camlab88-render.json) is skipped; each frame is "
    "written atomically and a failed frame or dead worker is retried and reported. The "
    "Sigma modes by default draw every frame on one emulated T5688 over the 9600-baud "
    "line, one after another as in 1984, and report line time and leaks; with --workers "
    "N or --dask they go parallel too: each frame on a fresh emulated T5688 (LUT loaded, "
    "screen cleared), byte-identical to the sequential frames since every frame starts "
    "from a cleared screen, but without the line statistics.")


def register(actions: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    s = actions.add_parser(
        "render", help="finished frames on the emulated Sigma T5688 or in true colour (§6.4)",
        description=DESCRIPTION)
    s.add_argument("motion", metavar="CHECKPOINT|SESSION")
    s.add_argument("views", metavar="VIEWS", help="the view file (from 'snooker ccl')")
    s.add_argument("--frames", type=frames_dir, metavar="DIR", required=True,
                   help="write DIR/frame_NNNNN.png")
    s.add_argument("--mode", choices=("period", "fixed", "adapted", "truecolour"),
                   default="period", help="(default period)")
    s.add_argument("--palette", choices=("fixed", "adaptive"), default="fixed",
                   help="the T5688's 256 colours: fixed (period) or chosen for the sequence")
    s.add_argument("--size", type=_size, default=(768, 512), metavar="WxH",
                   help="truecolour picture size (the Sigma modes are 768x512)")
    s.add_argument("--first", type=positive, metavar="N", help="first frame (default: all)")
    s.add_argument("--last", type=positive, metavar="M", help="last frame")
    s.add_argument("--lights", type=Path, metavar="FILE",
                   help="lights file: 'x y z [intensity | r g b]' a line (default: a canopy "
                   "of four bulbs)")
    s.add_argument("--no-specks", action="store_true", help="leave out the dust specks")
    s.add_argument("--no-wood", action="store_true",
                   help="truecolour: constant-shaded wood, as the Sigma modes draw it")
    _add_sequence_options(s)
    s.set_defaults(handler=render)


def _add_sequence_options(s: argparse.ArgumentParser) -> None:
    """Where the frames are rendered, and the films made of them (issue 14)."""
    s.add_argument("--workers", type=positive, metavar="N",
                   help="processes (truecolour default: one per core; Sigma modes: "
                   "sequential unless given; --dask local: its workers)")
    s.add_argument("--dask", metavar="ADDRESS|local",
                   help="render on a Dask cluster (a scheduler address, or 'local')")
    s.add_argument("--mp4", type=_movie(".mp4"), metavar="FILE",
                   help="also film the frames: H.264 at 25 frames/s, no sound")
    s.add_argument("--gif", type=_movie(".gif"), metavar="FILE",
                   help="also film the frames as a GIF at 25 frames/s")


def _movie(ext: str):  # an argparse type
    def check(text: str) -> Path:
        if Path(text).suffix.lower() != ext:
            raise argparse.ArgumentTypeError(f"{text}: expected a {ext} file")
        return Path(text)
    return check


def render(args: argparse.Namespace) -> int:
    from apps.snooker.camera.views import ViewFileError, read_views
    from apps.snooker.checkpoint import CheckpointError
    from apps.snooker.film.schedule import FilmError
    from apps.snooker.render.lights import LightsError, read_lights
    from apps.snooker.render.scene import load_scene
    from apps.snooker.render.sequence import SequenceError, select_views
    from apps.snooker.session import SessionError

    if args.mode == "truecolour" and args.palette != "fixed":
        return fail(COMMAND, "--palette is for the 256-colour Sigma modes (period, fixed)")
    if args.mode != "truecolour" and args.size != (768, 512):
        return fail(COMMAND, f"--mode {args.mode} draws the T5688's 768x512 screen; --size "
                    "is for truecolour")
    try:
        lights = read_lights(args.lights) if args.lights is not None else None
        scene = load_scene(args.motion, lights)
        views = select_views(read_views(args.views), scene, args.first, args.last,
                             str(args.views))
        return _render(args, scene, views)
    except KeyboardInterrupt:  # one line; cli.main gives the exit status (130, or 143)
        print(f"{COMMAND}: interrupted; the frames written so far stay, and the same "
              "command resumes from them", file=sys.stderr)
        raise
    except (CheckpointError, SessionError, ViewFileError, LightsError, SequenceError,
            FilmError, OSError) as exc:
        return fail(COMMAND, exc)


def _render(args: argparse.Namespace, scene, views) -> int:
    from apps.snooker.film.movie import write_movie
    from apps.snooker.film.pipeline import frame_files

    out = Path(args.frames)
    if args.mode == "truecolour":
        note = _truecolour(args, scene, views, out)
    else:
        note = _sigma(args, scene, views, out)
    for movie in (args.mp4, args.gif):
        if movie is not None:
            write_movie(frame_files(out, views), movie)
            note += f"; {movie}"
    print(f"{COMMAND}: {len(views)} frames ({views[0].frame}-{views[-1].frame}) -> {out}"
          f"{note}", file=sys.stderr)
    return 0


def _truecolour(args: argparse.Namespace, scene, views, out: Path) -> str:
    from apps.snooker.film.pipeline import FilmLook, shoot
    from apps.snooker.film.progress import progress_bar

    look = FilmLook(args.size[0], args.size[1], not args.no_specks, True, 1, not args.no_wood)
    r = shoot(scene, views, out, look, args.dask, args.workers, progress_bar(COMMAND),
              manifest=RECORD)
    return (f"; {len(r.rendered)} rendered, {len(r.skipped)} already there"
            + "".join(f"; frame {f} retried ({why})" for f, why in r.retries))


@dataclass(frozen=True)
class SigmaFrames:
    """One frame on a fresh emulated T5688 (set up, LUT loaded, the frame's orders over the
    9600-baud line, the screen read back) -> PNG bytes: a picklable renderer for the film
    scheduler's workers. Byte-identical to one terminal drawing frame after frame, because
    every frame starts from a cleared screen (checked in tests/snooker_render/test_parallel.py)."""

    mode: str
    specks: bool
    palette_sha: str
    palette: object = field(repr=False, compare=False)

    def __call__(self, scene, task) -> bytes:
        from apps.snooker.render.sequence import render_sequence
        from base.png import png_bytes
        from emulator.sigma import Terminal

        f = next(render_sequence(scene, [task.view], self.mode, (768, 512), self.palette,
                                 lambda: Terminal("t5688"), self.specks))
        return png_bytes(f.image)


def sigma_frames(mode: str, specks: bool, palette) -> SigmaFrames:
    import hashlib

    import numpy as np

    lut = np.ascontiguousarray(palette.linear, dtype=np.float64).tobytes()
    return SigmaFrames(mode, specks, hashlib.sha256(lut).hexdigest()[:32], palette)


def _sigma_parallel(args: argparse.Namespace, scene, views, out: Path,
                    render: SigmaFrames) -> str:
    from apps.snooker.film.pipeline import FilmLook, shoot
    from apps.snooker.film.progress import progress_bar

    r = shoot(scene, views, out, FilmLook(specks=render.specks), args.dask, args.workers,
              progress_bar(COMMAND), manifest=RECORD, render=render)
    return (f"; {args.palette} palette; {len(r.rendered)} rendered (a fresh T5688 each), "
            f"{len(r.skipped)} already there; line statistics: render without --workers"
            + "".join(f"; frame {f} retried ({why})" for f, why in r.retries))


def _sigma(args: argparse.Namespace, scene, views, out: Path) -> str:
    from apps.snooker.render.sequence import choose_palette

    palette = choose_palette(scene, views, args.palette,
                             progress(f"{COMMAND}: choosing 256 colours"))
    render = sigma_frames(args.mode, not args.no_specks, palette)
    if args.workers or args.dask:
        return _sigma_parallel(args, scene, views, out, render)
    stats = _sigma_sequential(args, scene, views, out, palette)
    _record(scene, views, out, render)
    return stats


def _record(scene, views, out: Path, render: SigmaFrames) -> None:
    """The frames just drawn, in the resume record (a parallel rerun skips them)."""
    from apps.snooker.film.pipeline import FilmLook, film_digest
    from apps.snooker.film.schedule import Manifest, frame_file
    from apps.snooker.film.task import task_key

    look = FilmLook(specks=render.specks)
    record, digest = Manifest(out / RECORD), film_digest(scene, render)
    for v in views:
        png = frame_file(out, int(v.frame)).read_bytes()  # what was just moved into place
        record.put(int(v.frame), task_key(digest, look.task(v)), png)
    record.save()


def _sigma_sequential(args: argparse.Namespace, scene, views, out: Path,
                      palette) -> str:
    from apps.snooker.render.sequence import render_sequence
    from emulator.png import frame_path, write_png
    from emulator.sigma import Terminal

    out.mkdir(parents=True, exist_ok=True)
    stage = Path(tempfile.mkdtemp(prefix=".render-", dir=out))
    show = progress(COMMAND)
    line = leaks = gaps = 0.0
    try:  # every frame goes to a staging directory first: nothing half-written
        for k, f in enumerate(render_sequence(scene, views, args.mode, args.size, palette,
                                              lambda: Terminal("t5688"), not args.no_specks,
                                              not args.no_wood),
                              start=1):
            write_png(f.image, frame_path(stage, f.frame))
            line += f.line_seconds or 0.0
            leaks += f.leaks or 0
            gaps += f.gaps or 0
            if show is not None:
                show(k, len(views))
        for f in sorted(stage.iterdir()):
            os.replace(f, out / f.name)
    finally:
        shutil.rmtree(stage, ignore_errors=True)
    n = len(views)
    return (f"; {args.palette} palette; line time {line:.1f} s at 9600 baud "
            f"({line / n:.1f} s a frame); leaking pixels {int(leaks)}"
            f" ({leaks / n:.1f} a frame), gaps {int(gaps)}")
