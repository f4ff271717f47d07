"""The ``--events FILE`` option of the interactive programs on the emulated Rainbow (snooker
play, snooker camera, ca program): scripted mouse and keyboard input, one language for all
(protocols/rainbow/script.py, docs/harness.md)."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from camlab88.replay_policy import KEEP

if TYPE_CHECKING:
    from camlab88.emulator.harness import RunOptions
    from camlab88.protocols.rainbow.script import Player

HEADLESS_NEEDS_EVENTS = ("Headless it needs --events (the run ends with the script) or "
                         "--stop-after N.")


def add_events_option(p: argparse.ArgumentParser) -> None:
    p.add_argument("--events", metavar="FILE",
                   help="scripted mouse/keyboard input (the Rainbow script format, "
                   "docs/harness.md: move, glide, press, release, click, drag, key, type, "
                   "wait)").replay = KEEP


def events_player(path: str | None) -> Player | None:
    """The --events script's player, or None without one (ScriptError names file:line)."""
    from camlab88.protocols.rainbow.script import Player, load

    return Player(load(path)) if path else None


def scripted_run_options(args: argparse.Namespace, command: str, player: Player | None,
                         idle_frames: int | None = 100) -> RunOptions:
    """The run options of a program driven by the mouse and keyboard: a window is wanted
    unless the --events script (or --stop-after) gives a headless run an end; a run nobody
    watches (headless, or one that ends in a --screenshot) with neither stops after
    ``idle_frames`` frames, so it always ends."""
    from camlab88.runopts import run_options, unattended

    useful = "playing the --events script" if player else (
        "for --stop-after frames" if args.stop_after else None)
    opts = run_options(args, command, useful, "give --headless with --events FILE",
                       getattr(args, "_argv", None))
    if idle_frames and unattended(opts) and player is None and opts.stop_after is None:
        opts.stop_after = idle_frames
    return opts
