"""``camlab88 ca ...``: the programmable cellular automaton of thesis chapter 7."""

from __future__ import annotations

import argparse

from camlab88.areas import register_area

ACTIONS = ("run", "convert", "replay", "library", "program", "film", "actors")
HELP = "the programmable cellular automaton (chapter 7)"
DESCRIPTION = """\
The programmable cellular automaton of thesis chapter 7: rule files, patterns, logs and \
scripts."""


def register(subparsers: argparse._SubParsersAction) -> None:
    register_area(subparsers, __name__, ACTIONS)

