"""``camlab88 rainbow ...``: render a scene file; run, serve or replay the emulator."""

from __future__ import annotations

import argparse
from typing import Any

from camlab88.areas import register_area

HELP = "the Rainbow workstation emulator"
ACTIONS = ("render", "run", "serve", "replay")
__all__ = ["ACTIONS", "register"]


def __getattr__(name: str) -> Any:
    """The host-input adapters under their old names (now emulator.rainbow.host_input)."""
    if name in ("host_to_rainbow_event", "tablet_event"):
        from emulator.rainbow import host_input

        return getattr(host_input, name)
    raise AttributeError(name)


def register(subparsers: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    register_area(subparsers, __name__, "rainbow", HELP, ACTIONS,
                  "The Cambridge Rainbow workstation: pads, clusters, band structure, "
                  "video processor.")
