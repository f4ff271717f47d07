"""``camlab88 ca program``: the interactive cellular automaton on the emulated Rainbow."""

from __future__ import annotations

import argparse
import sys

from camlab88.replay_policy import KEEP, SCRATCH
from camlab88.runopts import add_run_options, fail, unattended
from camlab88.scriptopts import (
    HEADLESS_NEEDS_EVENTS,
    add_events_option,
    events_player,
    scripted_run_options,
)

COMMAND = "camlab88 ca program"
KEYS = """\
left button pans; middle: menus; right: edit / step; Finish (menu) or close the window to \
quit"""
TEMPLATE = "Log/k,RecordPansAndZooms/s,Checkpoint,Script/k,ReplayPansAndZooms/s"
# Tripos keyword -> the --flag form's destination (section 7.3.1)
TRIPOS_DEST = {"Log": "log", "RecordPansAndZooms": "record_pans", "Checkpoint": "checkpoint",
               "Script": "script", "ReplayPansAndZooms": "replay_pans"}

DESCRIPTION = f"""\
The interactive cellular automaton on the emulated Rainbow: mouse (left button pans, middle \
button menus, right button edits / steps) and keyboard. Log, RecordPansAndZooms, Checkpoint, \
Script and ReplayPansAndZooms as in section 7.3.1. {HEADLESS_NEEDS_EVENTS} A --screenshot run \
writes no log and no checkpoint."""
EPILOG = f"""\
The section 7.3.1 arguments come in two forms: the thesis's Tripos form, as positional words \
(template {TEMPLATE}; /k: the keyword must be given before its value, /s: a switch; \
Checkpoint's keyword may be left out), e.g. `camlab88 ca program Log run.log \
RecordPansAndZooms Checkpoint 50`; and ours, the --flag form: Log/k = --log, \
RecordPansAndZooms/s = --record-pans, Checkpoint = --checkpoint, Script/k = --script, \
ReplayPansAndZooms/s = --replay-pans. Keywords are matched in any case; KEY=value works too. \
Give each argument in one form only."""


HELP = "the interactive program on the emulated Rainbow (sections 7.3.1-2)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("tripos", nargs="*", metavar="ARG",
                   help=f"the thesis's Tripos form: {TEMPLATE} (see below)")
    p.add_argument("--rules", default="life",
                   help="rule file or library name (life)").replay = KEEP
    p.add_argument("--pattern", help="pattern loaded at the centre of the view").replay = KEEP
    p.add_argument("--log", metavar="L",
                   help="Log: record every intervention in file L").replay = SCRATCH
    p.add_argument("--record-pans", action="store_true",
                   help="RecordPansAndZooms: the log also records pans and zooms").replay = KEEP
    p.add_argument("--checkpoint", default=0, type=int, metavar="N",
                   help="Checkpoint: write L<generation> every N generations").replay = KEEP
    p.add_argument("--script", metavar="S", help="Script: replay the log S").replay = KEEP
    p.add_argument("--replay-pans", action="store_true",
                   help="ReplayPansAndZooms: also repeat the script's pans and "
                        "zooms").replay = KEEP
    p.add_argument("--start", type=int, metavar="G",
                   help="begin the script at generation G (asked for in a window; without a window "
                        "or with --screenshot, the Log's first generation)").replay = KEEP
    p.add_argument("--edges", choices=["wrap", "bounded"],
                   help="plane edges (default wrap; a script's log header decides)").replay = KEEP
    p.add_argument("--seed", type=int,
                   help="seed of random outcomes (default 0; a script's log header "
                        "decides)").replay = KEEP
    p.add_argument("--random", action="store_true",
                   help="truly random outcomes (§8.1): a seed drawn from the operating system, "
                        "printed and written to the Log's header (and a recording), so a "
                        "replay repeats the run")
    add_events_option(p)
    add_run_options(p)
    p.add_argument("--json", action="store_true",
                   help="print the final statistics as JSON").replay = KEEP


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.ca.log import LogError
    from camlab88.apps.ca.patterns import PatternError
    from camlab88.apps.ca.rules import RuleError
    from camlab88.protocols.rainbow.script import ScriptError

    try:
        _apply_tripos(args)
        _truly_random(args)
        player = events_player(args.events)
        opts = scripted_run_options(args, COMMAND, player)
        if args.script and args.start is None and player is None and unattended(opts):
            args.start = _first_generation(args.script)
        options = _options(args, preview=opts.screenshot is not None)
        stats = _run(options, player, opts)
    except (OSError, LogError, RuleError, PatternError, ScriptError, ValueError) as exc:
        # TriposArgsError is a ValueError
        return fail(COMMAND, exc)
    _print_stats(stats, args.json)
    _report_files(options)
    return 0


def _truly_random(args: argparse.Namespace) -> None:
    """--random (§8.1's "truly random" choice): the seed comes from the operating system.
    It is printed, the Log's header records it (so a Script replays the run), and the
    recording's command line carries it as --seed N, so a replay repeats it too."""
    if not args.random:
        return
    if args.seed is not None:
        raise ValueError("give --random or --seed, not both")
    import secrets

    from camlab88.replay_policy import MAX_NUMBER

    args.seed = secrets.randbelow(MAX_NUMBER + 1)  # 30 bits: what a replay accepts
    argv = list(getattr(args, "_argv", None) or sys.argv[1:])
    argv[argv.index("--random"):argv.index("--random") + 1] = ["--seed", str(args.seed)]
    args._argv = argv
    print(f"{COMMAND}: truly random outcomes: seed {args.seed} (from the operating system; "
          "the log and a recording keep it)", flush=True)


def _first_generation(script: str) -> int:
    """Where a --script run nobody can answer begins: the Log's first generation (the
    start question is asked only in a window, or of an --events script)."""
    from camlab88.apps.ca.log import read_log

    first = min((e.generation for e in read_log(script)), default=0)
    print(f"{COMMAND}: beginning the script at generation {first}, the Log's first "
          "(--start G begins elsewhere)", file=sys.stderr)
    return first


def _report_files(options) -> None:
    """Name the Log (and where its checkpoints go) that the run kept on disk."""
    if options.log is None:
        return
    every = (f"; a checkpoint every {options.checkpoint} generations beside it as "
             f"{options.log}<generation>" if options.checkpoint else "")
    print(f"{COMMAND}: the Log is in {options.log}{every}", file=sys.stderr)


def _apply_tripos(args: argparse.Namespace) -> None:
    """The Tripos-form words into the --flag form's fields; one form per argument."""
    from camlab88.tripos_args import TriposArgsError, read_args

    defaults = {"log": None, "record_pans": False, "checkpoint": 0, "script": None,
                "replay_pans": False}
    for keyword, value in read_args(args.tripos, TEMPLATE).items():
        dest = TRIPOS_DEST[keyword]
        if getattr(args, dest) != defaults[dest]:
            flag = "--" + dest.replace("_", "-")
            raise TriposArgsError(f"{keyword} given twice: in the Tripos form and as {flag}")
        if dest == "checkpoint":
            value = _checkpoint(str(value))
        setattr(args, dest, value)


def _checkpoint(text: str) -> int:
    from camlab88.tripos_args import TriposArgsError

    try:
        return int(text)
    except ValueError:
        raise TriposArgsError(f"Checkpoint {text!r}: a number of generations") from None


def _options(args: argparse.Namespace, preview: bool):
    """The program's options; a screenshot (preview) run keeps no log and no checkpoints,
    so it never rewrites the user's files."""
    from camlab88.apps.ca.program.program import Options

    return Options(rules=args.rules, pattern=args.pattern,
                   log=None if preview else args.log, record_pans=args.record_pans,
                   checkpoint=0 if preview else max(0, args.checkpoint), script=args.script,
                   replay_pans=args.replay_pans, start=args.start, edges=args.edges,
                   seed=args.seed)


def _run(options, player, opts) -> dict:
    from camlab88.apps.ca.program.program import CAProgram
    from camlab88.emulator.harness import run
    from camlab88.emulator.harness.rainbow import RainbowTarget
    from camlab88.emulator.machine import RainbowMachine

    machine = RainbowMachine(record=opts.record is not None)
    prog = CAProgram(machine.client, options)

    def step() -> bool:
        prog.frame()
        return not prog.finished

    target = RainbowTarget(machine, step, "camlab88 ca", KEYS, player, unattended(opts),
                           program=prog)
    target.escape_is_a_key = True  # Esc closes a question, or finishes when none is open
    run(target, opts)
    return prog.session.statistics()


def _print_stats(stats: dict, as_json: bool) -> None:
    from camlab88.apps.ca.stats_text import stats_text

    print(stats_text(stats, as_json))
