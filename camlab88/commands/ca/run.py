"""``camlab88 ca run``: rules run on a pattern headless, with statistics."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from camlab88.runopts import check_output, fail

DESCRIPTION = """\
Load RULES and PATTERN (paths or library names), place the pattern's reference point at the \
centre of the 65536x65536 plane, run N generations and print the statistics of the Statistics \
menu."""


HELP = "run rules on a pattern headless and print statistics"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--rules", required=True, help="rule file or library name (e.g. life)")
    p.add_argument("--pattern", required=True,
                   help="pattern file (.pat native, .rle, .cells) or library name")
    p.add_argument("--generations", type=int, required=True, help="generations to run")
    p.add_argument("--json", action="store_true", help="print one JSON object last")
    p.add_argument("--edges", default="wrap", choices=["wrap", "bounded"],
                   help="plane edges wrap round (torus) or are bounded (default wrap)")
    p.add_argument("--seed", default=0, type=int,
                   help="seed of the reproducible random outcomes (default 0)")
    p.add_argument("--orientation", default="identity",
                   help="one of the eight orientations (identity, rot90, ... "
                        "antitranspose)")
    p.add_argument("--every", default=0, type=int,
                   help="also print a statistics line every N generations")
    p.add_argument("--png", metavar="PATH",
                   help="also write a picture of the final population's bounding box")
    p.add_argument("--zoom", default=4, type=int, help="pixels per cell for --png")
    p.add_argument("--monochrome", action="store_true", help="--png in white on black")
    p.add_argument("--engine", default="auto", choices=["auto", "hashlife", "direct"],
                   help="hashlife jumps (deterministic rules only), direct steps one "
                        "generation at a time; auto picks hashlife for long runs (default)")
    p.add_argument("--memory", default=512, type=int, metavar="MB",
                   help="HashLife node-table limit; past it the table is "
                        "garbage-collected (default 512)")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.ca import library
    from camlab88.apps.ca.engine import CENTRE, Engine
    from camlab88.apps.ca.patterns import PatternError, check_run, read_pattern
    from camlab88.apps.ca.rules import RuleError, load_rules
    from camlab88.apps.ca.seed import check_seed

    try:
        check_seed(args.seed)  # the kernels take an int64: a 20-digit seed is an error
        rules = load_rules(library.rules_path(args.rules))
        pattern = read_pattern(library.pattern_path(args.pattern))
        check_run(args.pattern, pattern)  # the engine's cost, before it is built
        grid = pattern.placed_grid(CENTRE, CENTRE, args.orientation)  # a dense pattern's
        cells = pattern.placed(CENTRE, CENTRE, args.orientation) if grid is None else None
    except (FileNotFoundError, RuleError, PatternError, ValueError) as exc:
        print(f"camlab88 ca run: {exc}", file=sys.stderr)
        return 2
    if args.generations < 0:
        print("camlab88 ca run: --generations must be >= 0", file=sys.stderr)
        return 2
    if args.png:  # a directory or read-only place is refused before the generations run
        check_output("camlab88 ca run", Path(args.png), "write the picture to", (".png",))
    from camlab88.apps.ca.jump_progress import ProgressLine

    engine = Engine(rules, edges=args.edges, seed=args.seed, algorithm=args.engine)
    engine.hashlife_memory = args.memory << 20
    engine.set_grid(*grid) if grid is not None else engine.set_cells(*cells)
    try:
        _advance(engine, args, ProgressLine)
    except (ValueError, MemoryError) as exc:  # HashLife forced where it cannot run
        print(f"camlab88 ca run: {exc}", file=sys.stderr)
        return 2
    stats = engine.stats()
    stats["origin"] = [CENTRE, CENTRE]
    if args.png and not _write_png(engine, args):
        return 1
    _print_stats(stats, args.json)
    return 0


def _write_png(engine, args: argparse.Namespace) -> bool:
    from camlab88.apps.ca.program.picture import picture
    from camlab88.base.png import write_png

    try:
        write_png(picture(engine, args.zoom, args.monochrome), args.png)
    except OSError as exc:  # a full disk: the old picture is left as it was
        fail("camlab88 ca run", exc, 1)
        return False
    print(f"wrote {args.png}", file=sys.stderr if args.json else sys.stdout)
    return True


def _advance(engine, args: argparse.Namespace, progress) -> None:
    """Run ``args.generations``, printing statistics every ``args.every`` on the way."""
    done = 0
    while done < args.generations:
        chunk = args.generations - done
        if args.every > 0:
            chunk = min(chunk, args.every)
        engine.step(chunk, progress(start_generation=done))
        done += chunk
        if args.every > 0 and done < args.generations:
            _print_stats(engine.stats(), False)


def _print_stats(stats: dict, as_json: bool) -> None:
    from camlab88.apps.ca.stats_text import stats_text

    print(stats_text(stats, as_json))
