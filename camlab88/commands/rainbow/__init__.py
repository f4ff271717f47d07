"""``camlab88 rainbow ...``: render a scene file; run, serve or replay the emulator."""

from __future__ import annotations

import argparse

from camlab88.areas import register_area

HELP = "the Rainbow workstation emulator"
ACTIONS = ("render", "run", "serve", "replay")
__all__ = ["ACTIONS", "register"]


def register(subparsers: argparse._SubParsersAction) -> None:
    register_area(subparsers, __name__, "rainbow", HELP, ACTIONS,
                  "The Cambridge Rainbow workstation: pads, clusters, band structure, "
                  "video processor.")
