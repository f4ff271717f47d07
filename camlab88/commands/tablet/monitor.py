"""``camlab88 tablet monitor SOURCE``: one line per decoded tablet event."""

from __future__ import annotations

import argparse

from camlab88.commands.tablet import add_source_argument
from camlab88.runopts import positive

COMMAND = "camlab88 tablet monitor"

DESCRIPTION = """\
Print one line per decoded event: x and y in tablet units, pressure, buttons, proximity. An \
emulated tablet driven by the mouse needs a display; ?drive=demo runs without one."""


HELP = "print one line per decoded event"


def add_arguments(p: argparse.ArgumentParser) -> None:
    add_source_argument(p)
    p.add_argument("--raw", action="store_true", help="also print the raw bytes/reports in hex")
    p.add_argument("--count", type=positive, help="stop after N events (N >= 1)")
    p.add_argument("--seconds", type=float, help="stop after S seconds")
    p.add_argument("--screenshot", help="(emulated) save the window after a few frames and exit")


def run(args: argparse.Namespace) -> int:
    from camlab88.emulator.tablet_input.monitor import monitor_tablet

    return monitor_tablet(COMMAND, args.source, args.raw, args.count, args.seconds,
                          args.screenshot)
