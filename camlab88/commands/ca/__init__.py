"""``camlab88 ca ...``: the programmable cellular automaton of thesis chapter 7."""

from __future__ import annotations

ACTIONS = ("run", "convert", "replay", "library", "program", "film", "actors")
HELP = "the programmable cellular automaton (chapter 7)"
DESCRIPTION = """\
The programmable cellular automaton of thesis chapter 7: rule files, patterns, logs and \
scripts."""


