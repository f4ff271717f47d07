"""``camlab88 tablet calibrate SOURCE``: touch two corners; saved per device."""

from __future__ import annotations

import argparse

from camlab88.commands.tablet import add_source_argument

COMMAND = "camlab88 tablet calibrate"


def register(actions: argparse._SubParsersAction) -> None:
    s = actions.add_parser("calibrate", help="touch two corners; saved per device",
                           description="Touch the top-left then the bottom-right corner of "
                           "the working area. Saved under $CAMLAB88_CONFIG_DIR (else "
                           "~/.config/camlab88)/calibration.json.")
    add_source_argument(s)
    s.add_argument("--seconds", type=float, default=120.0, help="give up after S seconds")
    s.set_defaults(handler=calibrate)


def calibrate(args: argparse.Namespace) -> int:
    from emulator.tablet_input.calibrate import calibrate_tablet

    return calibrate_tablet(COMMAND, args.source, args.seconds)
