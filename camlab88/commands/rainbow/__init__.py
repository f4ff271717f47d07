"""``camlab88 rainbow ...``: render a scene file; run, serve or replay the emulator."""

from __future__ import annotations

import argparse

from camlab88.areas import register_area

ACTIONS = ("render", "run", "serve", "replay")
__all__ = ["ACTIONS", "register"]


def register(subparsers: argparse._SubParsersAction) -> None:
    register_area(subparsers, __name__, ACTIONS)
