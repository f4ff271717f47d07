"""``camlab88 tablet``: list, monitor, calibrate and emulate graphics tablets."""

from __future__ import annotations

import argparse

ACTIONS = ("list", "monitor", "calibrate", "emulate")
HELP = "graphics tablets: real (HID/serial) and emulated"
DESCRIPTION = """\
Graphics tablets over USB HID or serial, and an emulated tablet that speaks a real protocol \
on a pty."""
SOURCE_HELP = (
    "hid:VID:PID | serial:PORT?protocol=P[&baud=N] | URL?protocol=P (loop://, socket://...) | "
    "emulated:P[?drive=demo]; P = wacom4, summa-mm, bitpad1, bitpad2, calcomp, summa-flair"
)
__all__ = ["ACTIONS", "SOURCE_HELP", "add_source_argument", "register"]


def add_source_argument(p: argparse.ArgumentParser) -> None:
    """The tablet to read: a SOURCE string (monitor, calibrate)."""
    p.add_argument("source", metavar="SOURCE", help=SOURCE_HELP)

