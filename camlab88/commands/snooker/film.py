"""``camlab88 snooker film CHECKPOINT|SESSION SCRIPT.ccl --out shot.mp4``: the chapter-6
pipeline in one command (thesis 6.3.1, 6.4) — camera script -> views -> frames -> film, with
``shot.views`` and ``shot_frames/frame_NNNNN.png`` kept beside the film. Truecolour frames
render in parallel (a local pool, or ``--dask ADDRESS|local``) and resume; the Sigma modes
draw on one emulated T5688 over the 9600-baud line, frame after frame, as in 1984."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from camlab88.apps.snooker.render.modes import MODES
from camlab88.argtypes import film_path, frame_size
from camlab88.commands.snooker import add_dask_options, add_looks_options
from camlab88.runopts import fail, positive

COMMAND = "camlab88 snooker film"


def _word(text: str) -> str:
    if not (1 <= len(text) <= 8 and all(c.isascii() and c.isprintable() for c in text)):
        raise argparse.ArgumentTypeError(f"{text!r}: 1 to 8 printable ASCII letters")
    return text.upper()

DESCRIPTION = """\
Interpret the camera script over the shot, render every frame and film them at 25 frames/s \
(no sound). Beside --out: OUT.views and OUT_frames/. Frames already rendered (complete PNGs \
of the right size) are skipped, so a stopped film resumes. Truecolour frames render on a \
local process pool (one process per core), or on a Dask cluster: --dask tcp://HOST:8786 \
(started with 'dask scheduler' and 'dask worker tcp://HOST:8786'), or --dask local."""


HELP = "camera script -> views -> rendered frames -> MP4/GIF (§6.3-6.4)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("motion", nargs="?", metavar="CHECKPOINT|SESSION")
    p.add_argument("script", nargs="?", metavar="SCRIPT.ccl", help="the camera script (§6.3.1)")
    p.add_argument("--titles", type=_word, metavar="WORD",
                   help="instead of a shot: the §6.5 title animation, WORD spelled by "
                        "giant lettered balls aimed with 'set up next shot' (e.g. CAMLAB88)")
    p.add_argument("--out", type=film_path, required=True, metavar="FILM",
                   help="the film: .mp4 (H.264) or .gif")
    p.add_argument("--gif", type=film_path, metavar="FILE", help="also a GIF of the film")
    p.add_argument("--mode", default="truecolour", choices=MODES,
                   help="truecolour (default), or a Sigma mode drawn on the emulated T5688")
    p.add_argument("--size", default="768x512", type=frame_size, metavar="WxH",
                   help="truecolour frame size")
    add_dask_options(p)
    p.add_argument("--workers", type=positive, metavar="N",
                   help="processes (default: one per core; --dask local: its workers)")
    p.add_argument("--motion-blur", action="store_true",
                   help="integrate each frame over a 1/50 s shutter (§6.4)")
    p.add_argument("--blur-samples", default=12, type=positive, metavar="N",
                   help="renders averaged over the shutter with --motion-blur")
    p.add_argument("--lights", type=Path, metavar="FILE", help="lights file (see render)")
    add_looks_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.snooker.checkpoint import CheckpointError
    from camlab88.apps.snooker.film.schedule import FilmError
    from camlab88.apps.snooker.render.lights import LightsError
    from camlab88.apps.snooker.session import SessionError
    from camlab88.filmrun import run_film

    if (args.titles is None) == (args.motion is None or args.script is None):
        return fail(COMMAND, "give CHECKPOINT|SESSION and SCRIPT.ccl, or --titles WORD")
    if args.titles and args.mode != "truecolour":
        return fail(COMMAND, "--titles renders in truecolour")
    if args.mode != "truecolour" and (args.size != (768, 512) or args.dask or args.motion_blur):
        return fail(COMMAND, f"--mode {args.mode} draws the T5688's 768x512 screen one "
                    "frame after another; --size, --dask and --motion-blur are truecolour's")
    return run_film(COMMAND, (args.motion, args.script), lambda: _film(args),
                    (CheckpointError, SessionError, LightsError, FilmError, OSError, ValueError))


def _film(args: argparse.Namespace) -> int:
    from camlab88.apps.snooker.camera.views import write_views
    from camlab88.apps.snooker.film import pipeline as P
    from camlab88.apps.snooker.film.movie import write_movie
    from camlab88.apps.snooker.film.progress import progress_bar
    from camlab88.apps.snooker.render.lights import LIGHT_PIXEL_BYTES, read_lights
    from camlab88.runopts import check_output

    paths = P.FilmPaths.beside(args.out)
    for out in (args.out, args.gif):  # before any work: a bad place fails now (status 2)
        if out is not None:
            check_output(COMMAND, Path(out), "write the film to", (".mp4", ".gif"))
    if args.titles:
        scene, views = P.title_film(args.titles)
        write_views(paths.views, views, [f"camlab88 snooker film --titles {args.titles}"])
    else:
        views = P.script_views(args.motion, args.script, paths.views)
        w, h = args.size if args.mode == "truecolour" else (768, 512)
        lights = (read_lights(args.lights, w * h * LIGHT_PIXEL_BYTES, f"at {w}x{h}")
                  if args.lights else None)
        scene = P.scene_of(args.motion, lights)
    if args.mode == "truecolour":
        look = P.FilmLook(args.size[0], args.size[1], not args.no_specks, True,
                          args.blur_samples if args.motion_blur else 1, not args.no_wood)
        report = P.shoot(scene, views, paths.frames, look, args.dask, args.workers,
                         progress_bar(COMMAND))
        note = (f"{len(report.rendered)} rendered, {len(report.skipped)} already there"
                + "".join(f"; frame {f} retried ({why})" for f, why in report.retries))
    else:
        note = _sigma_frames(args, scene, views, paths.frames)
    files = P.frame_files(paths.frames, views)
    for movie in (args.out, args.gif):
        if movie is not None:
            write_movie(files, movie)
    print(summary(args.out, args.gif, len(views), note, paths.views, paths.frames),
          file=sys.stderr)
    return 0


def summary(out: Path, gif: Path | None, n: int, note: str, views: Path, frames: Path) -> str:
    """The closing line: every file the film wrote, named."""
    films = f"{out} and {gif}" if gif is not None else f"{out}"
    return f"{COMMAND}: {n} frames -> {films} ({note}); views {views}, frames {frames}/"


def _sigma_frames(args: argparse.Namespace, scene, views, frames: Path) -> str:
    from camlab88.apps.snooker.film.schedule import frame_file
    from camlab88.apps.snooker.render.sequence import choose_palette, render_sequence
    from camlab88.base.atomicfile import write_atomic
    from camlab88.base.png import png_bytes
    from camlab88.emulator.harness.sigma_batch import t5688_link

    palette = choose_palette(scene, views, "fixed")
    frames.mkdir(parents=True, exist_ok=True)
    line = 0.0
    for f in render_sequence(scene, views, args.mode, (768, 512), palette,
                             t5688_link, not args.no_specks):
        write_atomic(frame_file(frames, f.frame), png_bytes(f.image))
        line += f.line_seconds or 0.0
    return f"{args.mode} on the emulated T5688, line time {line:.1f} s at 9600 baud"
