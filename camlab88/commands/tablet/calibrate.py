"""``camlab88 tablet calibrate SOURCE``: touch two corners; saved per device."""

from __future__ import annotations

import argparse

COMMAND = "camlab88 tablet calibrate"


def calibrate(args: argparse.Namespace) -> int:
    from camlab88.emulator.tablet_input.calibrate import calibrate_tablet

    return calibrate_tablet(COMMAND, args.source, args.seconds)
