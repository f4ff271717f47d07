"""``camlab88 sigma render|run``: the Sigma T5684/T5688 terminals headless or in a window."""

from __future__ import annotations

import argparse
from typing import Any

from camlab88.areas import register_area

HELP = "the Sigma T5684/T5688 terminals"
ACTIONS = ("render", "run")


def register(subparsers: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    register_area(subparsers, __name__, "sigma", HELP, ACTIONS,
                  "Emulated Sigma T5684 / T5688 graphics terminals.")


def _window_input(window: Any, term: Any) -> bool:
    """Window events -> the terminal (emulator.sigma.host_input); False on quit.  Kept for
    callers of the old name."""
    from emulator.host_input import Quit
    from emulator.sigma.host_input import to_terminal

    for ev in window.poll():
        if isinstance(ev, Quit):
            return False
        to_terminal(ev, term)
    return True
