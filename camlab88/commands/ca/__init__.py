"""``camlab88 ca ...``: the programmable cellular automaton of thesis chapter 7."""

from __future__ import annotations

import argparse

from camlab88.areas import register_area

ACTIONS = ("run", "convert", "replay", "library", "program", "film", "actors")


def register(subparsers: argparse._SubParsersAction) -> None:
    register_area(subparsers, __name__, ACTIONS)

