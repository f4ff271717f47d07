"""``camlab88 ca film RULES PATTERN --actors FILE --generations N --out film.mp4``: the
automaton with its cells as 3-D actors (thesis 8.1), the camera language over the grid,
rendered in truecolour on a local pool or Dask (resumable), or in the period mode on one
emulated T5688 over the 9600-baud line. Parse and wire only: apps/cafilm does the work."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from camlab88.argtypes import dask_address, film_path, frame_size
from camlab88.runopts import check_output, fail, positive

COMMAND = "camlab88 ca film"

DESCRIPTION = """\
Run RULES on PATTERN for N generations and film it with each cell state drawn as its actor \
(docs/ca_actors.md; a state without one is a coloured tile), births growing, deaths \
shrinking, moving cells gliding, F frames a generation. Beside --out: \
OUT_frames/frame_NNNNN.png; frames already rendered are kept, so a stopped truecolour film \
resumes (docs/ca_film.md)."""


HELP = "the automaton as a film of 3-D actors (chessmen...) (§8.1)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("rules", metavar="RULES", help="rule file or library name (life, maze)")
    p.add_argument("pattern", metavar="PATTERN", help="pattern file or library name")
    p.add_argument("--actors", metavar="FILE",
                   help="the actors file (e.g. examples/ca/chess.actors); without it "
                        "every cell is a tile")
    p.add_argument("--generations", type=positive, required=True, metavar="N")
    p.add_argument("--camera", metavar="SCRIPT",
                   help="camera script (CCL over the grid: events are generation numbers, "
                        "coordinates cells)")
    p.add_argument("--out", type=film_path, required=True, metavar="FILM", help=".mp4 or .gif")
    p.add_argument("--gif", type=film_path, metavar="FILE", help="also a GIF of the film")
    p.add_argument("--mode", default="truecolour", choices=["truecolour", "t5688"])
    p.add_argument("--size", default="768x512", type=frame_size, metavar="WxH",
                   help="truecolour frame size (t5688: its 768x512 screen)")
    p.add_argument("--frames-per-generation", default=8, type=positive, metavar="F")
    p.add_argument("--glide", default="all", metavar="all|none|S,S",
                   help="states whose cells glide to a neighbouring birth (default all)")
    p.add_argument("--samples", default=2, type=positive, metavar="S",
                   help="anti-aliasing: S x S samples a pixel (default 2)")
    p.add_argument("--lights", metavar="FILE",
                   help="lights file (x y z in cells; default four lights above the board)")
    p.add_argument("--edges", default="wrap", choices=["wrap", "dead"])
    p.add_argument("--seed", default=0, type=int)
    p.add_argument("--dask", type=dask_address, metavar="ADDRESS|local",
                   help="render on a Dask cluster")
    p.add_argument("--workers", type=positive, metavar="N",
                   help="processes (default: one per core)")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.snooker.film.schedule import FilmError
    from camlab88.filmrun import run_film

    if args.mode == "t5688" and (args.size != (768, 512) or args.dask or args.workers):
        return fail(COMMAND, "--mode t5688 draws the T5688's 768x512 screen one frame "
                    "after another; --size, --dask and --workers are truecolour's")
    return run_film(COMMAND, (args.actors, args.camera, args.lights), lambda: _film(args),
                    (FilmError, FileNotFoundError, OSError, ValueError))


def _film(args: argparse.Namespace) -> int:
    from camlab88.apps.cafilm.build import FilmSpec, build, rules_note
    from camlab88.apps.snooker.film.movie import write_movie
    from camlab88.apps.snooker.film.pipeline import FilmPaths
    from camlab88.apps.snooker.film.schedule import frame_file

    for out in (args.out, args.gif):  # before any work: a bad place fails now (status 2)
        if out is not None:
            check_output(COMMAND, out, "write the film to", (".mp4", ".gif"))
    spec = FilmSpec(args.rules, args.pattern, args.generations, args.actors, args.camera,
                    args.lights, args.frames_per_generation, args.glide, args.size,
                    args.samples, args.edges, args.seed)
    movie = build(spec)
    note = rules_note(movie, spec)
    if note:
        print(f"{COMMAND}: {note}", file=sys.stderr)
    frames = FilmPaths.beside(args.out).frames
    frames.mkdir(exist_ok=True)
    done = _truecolour(args, movie, frames) if args.mode == "truecolour" else \
        _period(movie, frames)
    files = [frame_file(frames, n) for n in range(1, movie.n_frames + 1)]
    for out in (args.out, args.gif):
        if out is not None:
            write_movie(files, out)
    films = f"{args.out} and {args.gif}" if args.gif else f"{args.out}"
    print(f"{COMMAND}: {movie.n_frames} frames -> {films} ({done}); frames {frames}/",
          file=sys.stderr)
    return 0


def _truecolour(args: argparse.Namespace, movie, frames: Path) -> str:
    from camlab88.apps.cafilm.film import shoot
    from camlab88.apps.snooker.film.progress import progress_bar

    report = shoot(movie, frames, args.dask, args.workers, progress_bar(COMMAND))
    return (f"{len(report.rendered)} rendered, {len(report.skipped)} already there"
            + "".join(f"; frame {f} retried ({why})" for f, why in report.retries))


def _period(movie, frames: Path) -> str:
    from camlab88.apps.cafilm.period import period_frames
    from camlab88.apps.snooker.film.schedule import frame_file
    from camlab88.base.atomicfile import write_atomic
    from camlab88.base.png import png_bytes
    from camlab88.emulator.harness.sigma_batch import t5688_link

    link = t5688_link()  # a T5688 on its 9600-baud line; the film is a host on its port

    def send(orders: bytes):
        start = link.port.now
        link.port.write(orders)
        link.wait()
        return link.frame(), float(link.port.now - start)

    line = 0.0
    for f in period_frames(movie, send):
        write_atomic(frame_file(frames, f.frame), png_bytes(f.image))
        line += f.line_seconds
    return f"t5688: Sigma orders only, line time {line:.1f} s at 9600 baud"
