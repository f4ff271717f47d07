"""``camlab88 tablet emulate``: an emulated tablet on a pty, driven by the mouse."""

from __future__ import annotations

import argparse

COMMAND = "camlab88 tablet emulate"


def emulate(args: argparse.Namespace) -> int:
    from camlab88.emulator.tablet_input.emulate import emulate_tablet

    return emulate_tablet(COMMAND, args.protocol, args.demo, args.seconds, args.screenshot)
