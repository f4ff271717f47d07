"""``camlab88 tablet calibrate SOURCE``: touch two corners; saved per device."""

from __future__ import annotations

import argparse

from camlab88.commands.tablet import add_source_argument

COMMAND = "camlab88 tablet calibrate"

DESCRIPTION = """\
Touch the top-left then the bottom-right corner of the working area. Saved under \
$CAMLAB88_CONFIG_DIR (else ~/.config/camlab88)/calibration.json."""


HELP = "touch two corners; saved per device"


def add_arguments(p: argparse.ArgumentParser) -> None:
    add_source_argument(p)
    p.add_argument("--seconds", default=120.0, type=float, help="give up after S seconds")


def run(args: argparse.Namespace) -> int:
    from camlab88.emulator.tablet_input.calibrate import calibrate_tablet

    return calibrate_tablet(COMMAND, args.source, args.seconds)
