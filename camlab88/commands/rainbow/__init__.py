"""``camlab88 rainbow ...``: render a scene file; run, serve or replay the emulator."""

from __future__ import annotations

import argparse

from camlab88.areas import register_area
from emulator.rainbow.host_input import host_to_rainbow_event, tablet_event

HELP = "the Rainbow workstation emulator"
ACTIONS = ("render", "run", "serve", "replay")
__all__ = ["ACTIONS", "host_to_rainbow_event", "register", "tablet_event"]  # old names


def register(subparsers: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    register_area(subparsers, __name__, "rainbow", HELP, ACTIONS,
                  "The Cambridge Rainbow workstation: pads, clusters, band structure, "
                  "video processor.")
