"""``camlab88 tablet monitor SOURCE``: one line per decoded tablet event."""

from __future__ import annotations

import argparse

from camlab88.commands.tablet import add_source_argument
from camlab88.runopts import positive

COMMAND = "camlab88 tablet monitor"


def register(actions: argparse._SubParsersAction) -> None:
    s = actions.add_parser("monitor", help="print one line per decoded event",
                           description="Print one line per decoded event: x and y in tablet "
                           "units, pressure, buttons, proximity. An emulated tablet driven "
                           "by the mouse needs a display; ?drive=demo runs without one.")
    add_source_argument(s)
    s.add_argument("--raw", action="store_true", help="also print the raw bytes/reports in hex")
    s.add_argument("--count", type=positive, default=None, help="stop after N events (N >= 1)")
    s.add_argument("--seconds", type=float, default=None, help="stop after S seconds")
    s.add_argument("--screenshot", default=None,
                   help="(emulated) save the window after a few frames and exit")
    s.set_defaults(handler=monitor)


def monitor(args: argparse.Namespace) -> int:
    from emulator.tablet_input.monitor import monitor_tablet

    return monitor_tablet(COMMAND, args.source, args.raw, args.count, args.seconds,
                          args.screenshot)
