"""``camlab88 kas ...``: the keyframe animation suite of thesis chapter 3.

The model programs (in-betweener, superimposer, plotter, exporter, schedule, the editor
model on a script) and the programs on the emulated Sigma T5684 (``edit``, ``path``,
``view``, run by the harness over a 9600-baud line).  File names may be library names.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.replay_policy import KEEP, TAPE
from camlab88.runopts import add_run_options

ACTIONS = ("inbetween", "superimpose", "plot", "export", "schedule", "edit_script",
           "path_script", "edit", "path", "view", "demo", "library", "paint")
HELP = "KAS, the keyframe animation suite (chapter 3)"
DESCRIPTION = """\
KAS: keyframe editor model, in-betweener, superimposer, viewer schedule and hard copy (thesis \
ch. 3). File names may be library names (see 'kas library')."""


def add_background_options(p: argparse.ArgumentParser) -> None:
    """The background options several of the area's commands share."""
    p.add_argument("--background", choices=["black", "white"], default="black").replay = KEEP


def add_front_options(p: argparse.ArgumentParser) -> None:
    """The front options several of the area's commands share."""
    p.add_argument("--script", type=Path,
                   help="event script (docs/kas.md; times optional)").replay = KEEP
    tablet = p.add_argument("--tablet", metavar="SOURCE",
                            help="tablet source (see 'camlab88 tablet'); default: the mouse")
    # not in a save state's identity: the state holds the tablet's input and its protocol
    tablet.replay, tablet.run_only = TAPE, True
    add_background_options(p)
    p.add_argument("--baud", type=int, default=9600).replay = KEEP
    add_run_options(p, stop_after=False)



def prepare_front(args: argparse.Namespace, command: str):
    """Everything that can refuse a KAS program's run, before anything is written: the
    script read, the display rule applied.
    Returns what ``run_front`` needs."""
    from camlab88.apps.kas.program.script import load_timed_script
    from camlab88.runopts import run_options

    if args.headless and args.script is None:
        raise ValueError("--headless needs --script")
    events = load_timed_script(args.script) if args.script is not None else []
    useful = "playing the --script" if args.script is not None else None
    opts = run_options(args, command, useful, "give --headless with --script FILE",
                       getattr(args, "_argv", None))
    return events, opts


def run_front(front, args: argparse.Namespace, command: str, keys: str,
              prepared=None, start=None):
    """Run a KAS program on an emulated T5684 over the line, on the harness: from a script
    and/or a window.  Returns the run (the session and its machine).  ``start``: what the
    program started from, kept in its save state (emulator.harness.input_log.StartState)."""
    from camlab88.apps.kas.program.layout import TABLET_AREA
    from camlab88.apps.kas.program.script import Session
    from camlab88.emulator.harness import run
    from camlab88.emulator.harness.sigma import SigmaProgramTarget, SigmaSessionRun
    from camlab88.emulator.machine import SigmaMachine
    from camlab88.emulator.tablet_input.pointer import TabletInput
    from camlab88.protocols.link import LineSettings
    from camlab88.protocols.sigma.keyboard import KEY_BYTES
    from camlab88.runopts import unattended

    events, opts = prepared or prepare_front(args, command)
    notices: list[str] = []
    # with --record the tablet's reports go on the session's tablet tape (a replay reads it)
    tablet = TabletInput(args.tablet, area=TABLET_AREA, notify=notices.append,
                         record=opts.record is not None)
    if tablet.live:  # a real stylus moves on the wall clock: keep the line time level with it
        opts.live = True
    machine = SigmaMachine("t5684", LineSettings(baud=args.baud))
    session = Session(front, machine.host, pointer=tablet)
    ran = SigmaSessionRun(machine, session)
    target = SigmaProgramTarget(ran, f"{command} - Sigma T5684", keys, frozenset(KEY_BYTES),
                                events, unattended(opts))
    if start is not None:
        target.give_start(start)
    try:
        run(target, opts)
    finally:
        tablet.close()
        for n in notices:
            print(f"{command}: {n}")
    return ran
