"""``camlab88 tablet monitor SOURCE``: one line per decoded tablet event."""

from __future__ import annotations

import argparse

COMMAND = "camlab88 tablet monitor"


def monitor(args: argparse.Namespace) -> int:
    from camlab88.emulator.tablet_input.monitor import monitor_tablet

    return monitor_tablet(COMMAND, args.source, args.raw, args.count, args.seconds,
                          args.screenshot)
