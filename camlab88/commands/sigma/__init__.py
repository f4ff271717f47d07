"""``camlab88 sigma render|run``: the Sigma T5684/T5688 terminals headless or in a window."""

from __future__ import annotations

import argparse

from camlab88.areas import register_area

ACTIONS = ("render", "run")
HELP = "the Sigma T5684/T5688 terminals"
DESCRIPTION = "Emulated Sigma T5684 / T5688 graphics terminals."
MODELS = ("t5684", "t5688")  # the --model choices of both actions


def register(subparsers: argparse._SubParsersAction) -> None:
    register_area(subparsers, __name__, ACTIONS)

