"""``camlab88 ca run``: rules run on a pattern headless, with statistics."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from camlab88.runopts import check_output, fail


def register(actions: argparse._SubParsersAction) -> None:
    p = actions.add_parser("run", help="run rules on a pattern headless and print statistics",
                         description="Load RULES and PATTERN (paths or library names), place "
                         "the pattern's reference point at the centre of the 65536x65536 plane, "
                         "run N generations and print the statistics of the Statistics menu.")
    p.add_argument("--rules", required=True, help="rule file or library name (e.g. life)")
    p.add_argument("--pattern", required=True,
                     help="pattern file (.pat native, .rle, .cells) or library name")
    p.add_argument("--generations", type=int, required=True, help="generations to run")
    p.add_argument("--json", action="store_true", help="print one JSON object last")
    p.add_argument("--edges", choices=("wrap", "bounded"), default="wrap",
                     help="plane edges wrap round (torus) or are bounded (default wrap)")
    p.add_argument("--seed", type=int, default=0,
                     help="seed of the reproducible random outcomes (default 0)")
    p.add_argument("--orientation", default="identity",
                     help="one of the eight orientations (identity, rot90, ... antitranspose)")
    p.add_argument("--every", type=int, default=0,
                     help="also print a statistics line every N generations")
    p.add_argument("--png", metavar="PATH",
                     help="also write a picture of the final population's bounding box")
    p.add_argument("--zoom", type=int, default=4, help="pixels per cell for --png")
    p.add_argument("--monochrome", action="store_true", help="--png in white on black")
    p.add_argument("--engine", choices=("auto", "hashlife", "direct"), default="auto",
                   help="hashlife jumps (deterministic rules only), direct steps one "
                   "generation at a time; auto picks hashlife for long runs (default)")
    p.add_argument("--memory", type=int, default=512, metavar="MB",
                   help="HashLife node-table limit; past it the table is garbage-collected "
                   "(default 512)")
    p.set_defaults(handler=_run)


def _run(args: argparse.Namespace) -> int:
    from apps.ca import library
    from apps.ca.engine import CENTRE, Engine
    from apps.ca.log import check_seed
    from apps.ca.patterns import PatternError, read_pattern
    from apps.ca.rules import RuleError, load_rules

    try:
        check_seed(args.seed)  # the kernels take an int64: a 20-digit seed is an error
        rules = load_rules(library.rules_path(args.rules))
        pattern = read_pattern(library.pattern_path(args.pattern))
        grid = pattern.placed_grid(CENTRE, CENTRE, args.orientation)  # a dense pattern's
        cells = pattern.placed(CENTRE, CENTRE, args.orientation) if grid is None else None
    except (FileNotFoundError, RuleError, PatternError, ValueError) as exc:
        print(f"camlab88 ca run: {exc}", file=sys.stderr)
        return 2
    if args.generations < 0:
        print("camlab88 ca run: --generations must be >= 0", file=sys.stderr)
        return 2
    if args.png:  # a directory or read-only place is refused before the generations run
        check_output("camlab88 ca run", Path(args.png), "write the picture to")
    from apps.ca.jump_progress import ProgressLine

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
    from apps.ca.program.picture import picture
    from base.png import write_png

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
    from apps.ca.stats_text import stats_text

    print(stats_text(stats, as_json))
