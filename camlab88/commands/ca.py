"""``camlab88 ca ...``: the programmable cellular automaton of thesis chapter 7, headless."""

from __future__ import annotations

import argparse
import json
import sys


def register(subparsers: argparse._SubParsersAction) -> None:
    ca = subparsers.add_parser("ca", help="the programmable cellular automaton (chapter 7)",
                               description="The programmable cellular automaton of thesis "
                               "chapter 7: rule files, patterns, logs and scripts.")
    sub = ca.add_subparsers(dest="ca_command", metavar="CA_COMMAND")
    sub.required = True

    run = sub.add_parser("run", help="run rules on a pattern headless and print statistics",
                         description="Load RULES and PATTERN (paths or library names), place "
                         "the pattern's reference point at the centre of the 65536x65536 plane, "
                         "run N generations and print the statistics of the Statistics menu.")
    run.add_argument("--rules", required=True, help="rule file or library name (e.g. life)")
    run.add_argument("--pattern", required=True,
                     help="pattern file (.pat native, .rle, .cells) or library name")
    run.add_argument("--generations", type=int, required=True, help="generations to run")
    run.add_argument("--json", action="store_true", help="print one JSON object last")
    run.add_argument("--edges", choices=("wrap", "bounded"), default="wrap",
                     help="plane edges wrap round (torus) or are bounded (default wrap)")
    run.add_argument("--seed", type=int, default=0,
                     help="seed of the reproducible random outcomes (default 0)")
    run.add_argument("--orientation", default="identity",
                     help="one of the eight orientations (identity, rot90, ... antitranspose)")
    run.add_argument("--every", type=int, default=0,
                     help="also print a statistics line every N generations")
    run.add_argument("--png", metavar="PATH",
                     help="also write a picture of the final population's bounding box")
    run.add_argument("--zoom", type=int, default=4, help="pixels per cell for --png")
    run.add_argument("--monochrome", action="store_true", help="--png in white on black")
    run.set_defaults(handler=_run)

    conv = sub.add_parser("convert", help="convert a pattern between native, RLE and .cells",
                          description="Read a pattern and write it in the format given by the "
                          "output file's extension (.rle, .cells, anything else native).")
    conv.add_argument("source", help="pattern file or library name")
    conv.add_argument("dest", help="output file")
    conv.set_defaults(handler=_convert)

    rep = sub.add_parser("replay", help="replay a Log as a Script up to a generation",
                         description="Start from the latest checkpoint (log name + generation) "
                         "at or before GENERATION, apply the script's interventions and rules "
                         "up to GENERATION, and print the statistics.")
    rep.add_argument("--script", required=True, help="log file written by a ca session")
    rep.add_argument("--generation", type=int, required=True)
    rep.add_argument("--edges", choices=("wrap", "bounded"), default="wrap")
    rep.add_argument("--seed", type=int, default=0)
    rep.add_argument("--json", action="store_true")
    rep.set_defaults(handler=_replay)

    lib = sub.add_parser("library", help="list the shipped rule sets and patterns")
    lib.set_defaults(handler=_library)


def _print_stats(stats: dict, as_json: bool) -> None:
    if as_json:
        print(json.dumps(stats, sort_keys=True))
        return
    box = stats["bbox"]
    kinds = ", ".join(f"{k}: {v}" for k, v in stats["by_type"].items()) or "none"
    print(f"generation {stats['generation']}  population {stats['population']}  "
          f"by type {{{kinds}}}  bbox {'empty' if box is None else tuple(box)}")


def _run(args: argparse.Namespace) -> int:
    from apps.ca import library
    from apps.ca.engine import CENTRE, Engine
    from apps.ca.patterns import PatternError, read_pattern
    from apps.ca.rules import RuleError, load_rules

    try:
        rules = load_rules(library.rules_path(args.rules))
        pattern = read_pattern(library.pattern_path(args.pattern))
        xs, ys, ts = pattern.placed(CENTRE, CENTRE, args.orientation)
    except (FileNotFoundError, RuleError, PatternError, ValueError) as exc:
        print(f"camlab88 ca run: {exc}", file=sys.stderr)
        return 2
    if args.generations < 0:
        print("camlab88 ca run: --generations must be >= 0", file=sys.stderr)
        return 2
    engine = Engine(rules, edges=args.edges, seed=args.seed)
    engine.set_cells(xs, ys, ts)
    done = 0
    while done < args.generations:
        chunk = args.generations - done
        if args.every > 0:
            chunk = min(chunk, args.every)
        engine.step(chunk)
        done += chunk
        if args.every > 0 and done < args.generations:
            _print_stats(engine.stats(), False)
    stats = engine.stats()
    stats["origin"] = [CENTRE, CENTRE]
    if args.png:
        _write_png(engine, args.png, args.zoom, args.monochrome)
    _print_stats(stats, args.json)
    return 0


def _write_png(engine, path: str, zoom: int, monochrome: bool) -> None:
    import os
    import tempfile

    from PIL import Image

    from apps.ca.engine import Rect
    from apps.ca.render import render

    box = engine.bbox() or Rect(0, 0, 0, 0)
    pad = 2
    rect = Rect(max(0, box.x0 - pad), max(0, box.y0 - pad), min(65535, box.x1 + pad),
                min(65535, box.y1 + pad))
    img = render(engine, rect, max(1, zoom), monochrome)
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(suffix=".png", dir=folder)
    os.close(fd)
    Image.fromarray(img).save(tmp)
    os.replace(tmp, path)


def _convert(args: argparse.Namespace) -> int:
    from apps.ca import library
    from apps.ca.patterns import PatternError, read_pattern, write_pattern

    try:
        write_pattern(args.dest, read_pattern(library.pattern_path(args.source)))
    except (FileNotFoundError, PatternError, ValueError) as exc:
        print(f"camlab88 ca convert: {exc}", file=sys.stderr)
        return 2
    return 0


def _replay(args: argparse.Namespace) -> int:
    from apps.ca.engine import Engine
    from apps.ca.log import LogError, start_from_script
    from apps.ca.rules import RuleError

    try:
        engine = start_from_script(args.script, args.generation,
                                   lambda: Engine(edges=args.edges, seed=args.seed))
    except (OSError, LogError, RuleError, ValueError, RuntimeError) as exc:
        print(f"camlab88 ca replay: {exc}", file=sys.stderr)
        return 2
    _print_stats(engine.stats(), args.json)
    return 0


def _library(args: argparse.Namespace) -> int:
    from apps.ca import library

    for kind, items in library.names().items():
        print(f"{kind}: {' '.join(items)}")
    return 0
