"""The save-state flags every harness command shares (docs/harness.md, "Save states and
seeking"): ``--save-state FILE`` (written when the run ends, or at ``--at SECONDS`` of
virtual time), ``--load-state FILE`` (continue from a state of the same program, version and
inputs). Under ``camlab88 replay`` the replay's own state options come first; the recorded
program's ``--load-state`` (the recording carries the file) is where its run began."""

from __future__ import annotations

import argparse
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

from camlab88.replay_policy import KEEP, SCRATCH

if TYPE_CHECKING:
    from camlab88.emulator.harness.program_state import StateOptions


def seconds(text: str) -> Fraction:
    """A virtual time in seconds, 0 or more (``2``, ``2.5``, ``5/2``)."""
    try:
        value = Fraction(text)
    except (ValueError, ZeroDivisionError):
        raise argparse.ArgumentTypeError(f"not a number of seconds: {text!r}") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"must be 0 or more, not {text}")
    return value


def add_state_options(p: argparse.ArgumentParser) -> None:
    """--save-state, --at, --load-state: run-only; in a replay the file saved is an output,
    and the state a run began from an input file the recording carries by content."""
    for action, kind in (
            (p.add_argument("--save-state", type=Path, metavar="FILE",
                            help="save the whole state (device + program) to FILE when the "
                            "run ends, or at --at SECONDS of virtual time"), SCRATCH),
            (p.add_argument("--at", type=seconds, metavar="SECONDS",
                            help="with --save-state: save at this virtual time (the run "
                            "goes on)"), KEEP),
            (p.add_argument("--load-state", type=Path, metavar="FILE",
                            help="continue from a state saved by the same program, version "
                            "and inputs"), KEEP)):
        action.replay, action.run_only = kind, True


def state_options(args: argparse.Namespace, command: str, active: Any) -> StateOptions:
    """The StateOptions of a run (always present: the window keys need them)."""
    from camlab88 import __version__
    from camlab88.emulator.harness.program_state import StateOptions
    from camlab88.runopts import check_output

    save, at, load = (getattr(args, n, None) for n in ("save_state", "at", "load_state"))
    if at is not None and save is None:
        raise SystemExit(f"{command}: --at needs --save-state FILE")
    if active is not None and getattr(active, "state", None) is not None:
        mine: StateOptions = active.state
        if mine.load is None and mine.load_data is None:
            mine.load = load  # the recorded run began from this state
        return mine
    if save is not None:
        check_output(command, Path(save), "save a state to")
    if load is not None and not Path(load).is_file():
        raise SystemExit(f"{command}: cannot read {load}: "
                         f"{'it is a directory' if Path(load).is_dir() else 'no such file'}")
    return StateOptions(save=save, at=at, load=load, version=__version__)
