"""``camlab88 link ...``: inspect link recordings and test connections (protocols.link.cli)."""

from __future__ import annotations

import argparse

from camlab88.areas import register_area

ACTIONS = ("dump", "stream", "echo")
HELP = "serial-line tools: dump recordings, extract streams, echo device"
DESCRIPTION = "Tools for the emulated serial line (see docs/link.md)."


def register(subparsers: argparse._SubParsersAction) -> None:
    register_area(subparsers, __name__, ACTIONS)
