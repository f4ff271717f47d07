"""``camlab88 snooker render CHECKPOINT|SESSION VIEWS --frames DIR``: finished frames
(thesis 6.4, 6.4.1) — ``period`` and ``fixed`` on the emulated Sigma T5688 over the
9600-baud line, ``truecolour`` in 24-bit at any size; frame_NNNNN.png numbered as the
checkpoint's frames (from 1). Truecolour frames render in parallel and resume through
apps.snooker.film's scheduler (a local pool, or ``--dask ADDRESS|local``); the Sigma modes
draw on one emulated T5688, frame after frame."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from camlab88.apps.snooker.render.modes import MODES
from camlab88.argtypes import frame_size, gif_file, mp4_file
from camlab88.commands.snooker import add_dask_options, add_looks_options
from camlab88.runopts import fail, frames_dir, positive, progress

COMMAND = "camlab88 snooker render"
RECORD = ".camlab88-render.json"  # the resume record, hidden among the frames

DESCRIPTION = """\
Render every frame of a view file over a checkpoint or session. --mode period: the 1984 \
program on the emulated T5688 over the 9600-baud line (firmware outlines + flood fill: \
polygon colour leaks past the anti-aliased edges, counted); fixed: the same with software \
Bresenham outlines (no leaks); adapted: firmware outlines anti-aliased where the firmware \
puts them (no leaks, period's line time); truecolour: 24-bit at --size. Writes \
DIR/frame_NNNNN.png numbered as the checkpoint's frames. Truecolour renders in parallel: one \
process per core (--workers N), or on a Dask cluster (--dask tcp://HOST:8786 from 'dask \
scheduler' + 'dask worker', or --dask local); it resumes: a frame whose PNG is complete and \
was made from the same shot, view and settings (DIR/.camlab88-render.json) is skipped; each \
frame is written atomically and a failed frame or dead worker is retried and reported. The \
Sigma modes by default draw every frame on one emulated T5688 over the 9600-baud line, one \
after another as in 1984, and report line time and leaks; with --workers N or --dask they go \
parallel too: each frame on a fresh emulated T5688 (LUT loaded, screen cleared), \
byte-identical to the sequential frames since every frame starts from a cleared screen, but \
without the line statistics."""


HELP = "finished frames on the emulated Sigma T5688 or in true colour (§6.4)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("motion", metavar="CHECKPOINT|SESSION")
    p.add_argument("views", metavar="VIEWS", help="the view file (from 'snooker ccl')")
    p.add_argument("--frames", type=frames_dir, required=True, metavar="DIR",
                   help="write DIR/frame_NNNNN.png")
    p.add_argument("--mode", default="period", choices=MODES, help="(default period)")
    p.add_argument("--palette", default="fixed", choices=["fixed", "adaptive"],
                   help="the T5688's 256 colours: fixed (period) or chosen for the "
                        "sequence")
    p.add_argument("--size", default="768x512", type=frame_size, metavar="WxH",
                   help="truecolour picture size (the Sigma modes are 768x512)")
    p.add_argument("--first", type=positive, metavar="N", help="first frame (default: all)")
    p.add_argument("--last", type=positive, metavar="M", help="last frame")
    p.add_argument("--lights", type=Path, metavar="FILE",
                   help="lights file: 'x y z [intensity | r g b]' a line (default: a "
                        "canopy of four bulbs)")
    add_looks_options(p)
    p.add_argument("--workers", type=positive, metavar="N",
                   help="processes (truecolour default: one per core; Sigma modes: "
                        "sequential unless given; --dask local: its workers)")
    add_dask_options(p)
    p.add_argument("--mp4", type=mp4_file, metavar="FILE",
                   help="also film the frames: H.264 at 25 frames/s, no sound")
    p.add_argument("--gif", type=gif_file, metavar="FILE",
                   help="also film the frames as a GIF at 25 frames/s")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.snooker.camera.views import ViewFileError, read_views
    from camlab88.apps.snooker.checkpoint import CheckpointError
    from camlab88.apps.snooker.film.schedule import FilmError
    from camlab88.apps.snooker.render.lights import (
        LIGHT_PIXEL_BYTES,
        LightsError,
        read_lights,
    )
    from camlab88.apps.snooker.render.scene import load_scene
    from camlab88.apps.snooker.render.sequence import SequenceError, select_views
    from camlab88.apps.snooker.session import SessionError

    if args.mode == "truecolour" and args.palette != "fixed":
        return fail(COMMAND, "--palette is for the 256-colour Sigma modes (period, fixed)")
    if args.mode != "truecolour" and args.size != (768, 512):
        return fail(COMMAND, f"--mode {args.mode} draws the T5688's 768x512 screen; --size "
                    "is for truecolour")
    from camlab88.runopts import check_output, check_output_dir

    check_output_dir(COMMAND, Path(args.frames))  # the one output rule, before the work
    for movie, kind in ((args.mp4, ".mp4"), (args.gif, ".gif")):
        if movie is not None:
            check_output(COMMAND, Path(movie), "write the film to", (kind,))
    try:
        w, h = args.size if args.mode == "truecolour" else (768, 512)
        lights = (read_lights(args.lights, w * h * LIGHT_PIXEL_BYTES, f"at {w}x{h}")
                  if args.lights is not None else None)
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
    from camlab88.apps.snooker.film.movie import write_movie
    from camlab88.apps.snooker.film.pipeline import frame_files

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
    from camlab88.apps.snooker.film.pipeline import FilmLook, shoot
    from camlab88.apps.snooker.film.progress import progress_bar

    look = FilmLook(args.size[0], args.size[1], not args.no_specks, True, 1, not args.no_wood)
    r = shoot(scene, views, out, look, args.dask, args.workers, progress_bar(COMMAND),
              manifest=RECORD)
    return (f"; {len(r.rendered)} rendered, {len(r.skipped)} already there"
            + "".join(f"; frame {f} retried ({why})" for f, why in r.retries))


def _sigma_parallel(args: argparse.Namespace, scene, views, out: Path, render) -> str:
    from camlab88.apps.snooker.film.pipeline import FilmLook, shoot
    from camlab88.apps.snooker.film.progress import progress_bar

    r = shoot(scene, views, out, FilmLook(specks=render.specks), args.dask, args.workers,
              progress_bar(COMMAND), manifest=RECORD, render=render)
    return (f"; {args.palette} palette; {len(r.rendered)} rendered (a fresh T5688 each), "
            f"{len(r.skipped)} already there; line statistics: render without --workers"
            + "".join(f"; frame {f} retried ({why})" for f, why in r.retries))


def _sigma(args: argparse.Namespace, scene, views, out: Path) -> str:
    from camlab88.apps.snooker.render.sequence import choose_palette
    from camlab88.apps.snooker.render.sigma_frames import record, render_staged, sigma_frames
    from camlab88.emulator.harness.sigma_batch import t5688_link

    palette = choose_palette(scene, views, args.palette,
                             progress(f"{COMMAND}: choosing 256 colours"))
    render = sigma_frames(args.mode, not args.no_specks, palette, t5688_link)
    if args.workers or args.dask:
        return _sigma_parallel(args, scene, views, out, render)
    t = render_staged(scene, views, out, args.mode, args.size, palette, t5688_link,
                      not args.no_specks, not args.no_wood, progress(COMMAND))
    record(scene, views, out, render, RECORD)
    n = len(views)
    return (f"; {args.palette} palette; line time {t.line:.1f} s at 9600 baud "
            f"({t.line / n:.1f} s a frame); leaking pixels {int(t.leaks)}"
            f" ({t.leaks / n:.1f} a frame), gaps {int(t.gaps)}")
