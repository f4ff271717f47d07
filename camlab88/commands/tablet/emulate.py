"""``camlab88 tablet emulate``: an emulated tablet on a pty, driven by the mouse."""

from __future__ import annotations

import argparse

COMMAND = "camlab88 tablet emulate"

DESCRIPTION = """\
Open a window; the mouse drives a tablet that writes its protocol's bytes to a \
pseudo-terminal (path printed) that any program can open as a serial port. Left button = tip, \
right = barrel, middle = button 2; key o = out of proximity, e = eraser end. Needs a display \
(the mouse), except with --demo. The emulator's controls work as in every window: F1 the keys, \
F5 pause / resume (the tablet sends nothing while paused), F6 one frame, F7 / F8 half / double \
speed, F11 the inspector, F12 a screenshot, Esc or closing the window quits."""


HELP = "an emulated tablet on a pty, driven by the mouse"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--protocol", default="summa-mm",
                   help="wacom4, summa-mm (default), bitpad1, bitpad2, calcomp, "
                        "summa-flair")
    p.add_argument("--demo", action="store_true", help="draw a scripted stroke, not the mouse")
    p.add_argument("--seconds", type=float, help="exit after S seconds")
    p.add_argument("--screenshot", help="save the window after a few frames, exit")


def run(args: argparse.Namespace) -> int:
    from camlab88.emulator.tablet_input.emulate import emulate_tablet

    return emulate_tablet(COMMAND, args.protocol, args.demo, args.seconds, args.screenshot)
