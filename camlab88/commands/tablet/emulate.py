"""``camlab88 tablet emulate``: an emulated tablet on a pty, driven by the mouse."""

from __future__ import annotations

import argparse

COMMAND = "camlab88 tablet emulate"


def register(actions: argparse._SubParsersAction) -> None:
    s = actions.add_parser("emulate", help="an emulated tablet on a pty, driven by the mouse",
                           description="Open a window; the mouse drives a tablet that writes "
                           "its protocol's bytes to a pseudo-terminal (path printed) that any "
                           "program can open as a serial port. Left button = tip, right = "
                           "barrel, middle = button 2; key o = out of proximity, e = eraser "
                           "end. Needs a display (the mouse), except with --demo.")
    s.add_argument("--protocol", default="summa-mm", help="wacom4, summa-mm (default), "
                   "bitpad1, bitpad2, calcomp, summa-flair")
    s.add_argument("--demo", action="store_true", help="draw a scripted stroke, not the mouse")
    s.add_argument("--seconds", type=float, default=None, help="exit after S seconds")
    s.add_argument("--screenshot", default=None, help="save the window after a few frames, exit")
    s.set_defaults(handler=emulate)


def emulate(args: argparse.Namespace) -> int:
    from emulator.tablet_input.emulate import emulate_tablet

    return emulate_tablet(COMMAND, args.protocol, args.demo, args.seconds, args.screenshot)
