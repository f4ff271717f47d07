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
    rep.add_argument("--edges", choices=("wrap", "bounded"),
                     help="only for logs that do not record their edges (default wrap)")
    rep.add_argument("--seed", type=int,
                     help="only for logs that do not record their seed (default 0)")
    rep.add_argument("--json", action="store_true")
    rep.set_defaults(handler=_replay)

    lib = sub.add_parser("library", help="list the shipped rule sets and patterns")
    lib.set_defaults(handler=_library)

    prog = sub.add_parser(
        "program", help="the interactive program on the emulated Rainbow (sections 7.3.1-2)",
        description="The interactive cellular automaton on the emulated Rainbow: mouse "
        "(left button pans, middle button menus, right button edits / steps) and keyboard. "
        "Log, RecordPansAndZooms, Checkpoint, Script and ReplayPansAndZooms as in section "
        "7.3.1.")
    prog.add_argument("--rules", default="life", help="rule file or library name (life)")
    prog.add_argument("--pattern", help="pattern loaded at the centre of the view")
    prog.add_argument("--log", metavar="L", help="Log: record every intervention in file L")
    prog.add_argument("--record-pans", action="store_true",
                      help="RecordPansAndZooms: the log also records pans and zooms")
    prog.add_argument("--checkpoint", type=int, default=0, metavar="N",
                      help="Checkpoint: write L<generation> every N generations")
    prog.add_argument("--script", metavar="S", help="Script: replay the log S")
    prog.add_argument("--replay-pans", action="store_true",
                      help="ReplayPansAndZooms: also repeat the script's pans and zooms")
    prog.add_argument("--start", type=int, metavar="G",
                      help="begin the script at generation G (asked for if omitted)")
    prog.add_argument("--edges", choices=("wrap", "bounded"),
                      help="plane edges (default wrap; a script's log header decides)")
    prog.add_argument("--seed", type=int,
                      help="seed of random outcomes (default 0; a script's log header decides)")
    prog.add_argument("--headless", action="store_true", help="no window")
    prog.add_argument("--events", metavar="FILE",
                      help="scripted mouse/keyboard input (see apps/ca/program/script_events.py)")
    prog.add_argument("--frames", type=int, metavar="N",
                      help="stop after N frames (default: until Finish; 100 headless)")
    prog.add_argument("--screenshot", metavar="PNG", help="save the last frame and exit")
    prog.add_argument("--scale", type=int, default=1, help="window scale factor")
    prog.add_argument("--json", action="store_true", help="print the final statistics as JSON")
    prog.set_defaults(handler=_program)


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

    from PIL import Image

    from apps.ca.engine import SIDE, Rect
    from apps.ca.render import render

    box = engine.bbox() or Rect(0, 0, 0, 0)
    pad = 2
    if engine.edges == "wrap":  # the box may cross the seam; so may the padded one
        rect = Rect((box.x0 - pad) % SIDE, (box.y0 - pad) % SIDE, (box.x1 + pad) % SIDE,
                    (box.y1 + pad) % SIDE)
    else:
        rect = Rect(max(0, box.x0 - pad), max(0, box.y0 - pad), min(SIDE - 1, box.x1 + pad),
                    min(SIDE - 1, box.y1 + pad))
    img = render(engine, rect, max(1, zoom), monochrome)
    from protocols.atomicfile import atomic_output

    with atomic_output(path) as fh:
        Image.fromarray(img).save(fh, format="PNG")


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
    from apps.ca.log import LogError, read_log_settings, resolve_settings, start_from_script
    from apps.ca.rules import RuleError

    try:
        edges, seed, warnings = resolve_settings(read_log_settings(args.script), args.edges,
                                                 args.seed)
        for w in warnings:
            print(f"camlab88 ca replay: warning: {w}", file=sys.stderr)
        engine = start_from_script(args.script, args.generation,
                                   lambda: Engine(edges=edges, seed=seed))
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


def _program(args: argparse.Namespace) -> int:
    from apps.ca.log import LogError
    from apps.ca.patterns import PatternError
    from apps.ca.program import script_events
    from apps.ca.program.program import Options
    from apps.ca.rules import RuleError

    opts = Options(rules=args.rules, pattern=args.pattern, log=args.log,
                   record_pans=args.record_pans, checkpoint=max(0, args.checkpoint),
                   script=args.script, replay_pans=args.replay_pans, start=args.start,
                   edges=args.edges, seed=args.seed)
    try:
        steps = script_events.read(args.events) if args.events else []
        frames = args.frames
        if frames is None and (args.headless or args.screenshot):
            frames = 100 if not steps else 0
        stats = run_program(opts, steps, frames, headless=args.headless,
                            screenshot=args.screenshot, scale=args.scale)
    except (OSError, LogError, RuleError, PatternError, script_events.ScriptError,
            ValueError) as exc:
        print(f"camlab88 ca program: {exc}", file=sys.stderr)
        return 2
    _print_stats(stats, args.json)
    return 0


def run_program(opts, steps: list, frames: int | None, headless: bool = True,
                screenshot: str | None = None, scale: int = 1, paced: bool = True) -> dict:
    """Run the program on an in-process Rainbow: scripted steps first, then ``frames``
    more frames (None: until Finish, or the window is closed)."""
    from apps.ca.program import script_events
    from apps.ca.program.program import CAProgram
    from emulator.rainbow.files import save_png
    from emulator.rainbow.session import in_process

    window = None
    quit_ = [False]
    session = in_process()
    if not headless:
        from emulator.window import Window

        window = Window("camlab88 ca", (768, 576), scale=scale)
    held = [0]

    def frame() -> None:
        if window is not None:
            from camlab88.commands.rainbow import host_to_rainbow_event
            from emulator.host_input import Quit

            for ev in window.poll():
                if isinstance(ev, Quit):
                    quit_[0] = True
                dev = host_to_rainbow_event(ev, held)
                if dev is not None:
                    session.inject(dev)
        program.frame()
        if window is not None:
            window.show(session.executor.last_frame)
            if paced and not screenshot:
                window.wait_frame(50)

    try:
        program = CAProgram(session.client, opts)
        done = lambda: program.finished or quit_[0]  # noqa: E731
        script_events.play(steps, session.inject, frame, done)
        n = 0
        while not done() and (frames is None or n < frames):
            frame()
            n += 1
        if screenshot:
            if window is not None:
                window.screenshot(screenshot)
            else:
                save_png(screenshot, session.executor.last_frame)
    finally:
        if window is not None:
            window.close()
    stats = program.session.statistics()
    return stats


def run_demo(headless: bool = False, screenshot: str | None = None, scale: int = 1,
             generations: int = 60) -> dict:
    """A short demo for ``camlab88 demo``: the Gosper glider gun in Life, stepped in auto
    mode for ``generations`` generations, with a pan and a zoom change on the way."""
    from apps.ca.program import script_events
    from apps.ca.program.demo import demo_events
    from apps.ca.program.program import Options

    steps = script_events.parse(demo_events(generations), "<ca demo>")
    return run_program(Options(rules="life", pattern="gosper_gun"), steps, 0, headless=headless,
                       screenshot=screenshot, scale=scale)
