"""``camlab88 snooker ...``: the snooker motion-development program (thesis ch. 6).

``camlab88 snooker [SESSION]`` with no action is ``snooker play [SESSION]``.
"""

from __future__ import annotations

import argparse

from camlab88.areas import register_area

ACTIONS = ("play", "simulate", "replay", "ccl", "visualise", "camera", "render", "film")


def register(subparsers: argparse._SubParsersAction) -> None:
    register_area(subparsers, __name__, ACTIONS)


def normalise_argv(argv: list[str]) -> list[str]:
    """``camlab88 snooker [SESSION] [options]`` is the interactive program: with no
    action named, insert ``play`` so the session file and options reach it."""
    if argv[:1] == ["snooker"]:
        rest = argv[1:]
        if not rest or rest[0] not in (*ACTIONS, "-h", "--help"):
            return ["snooker", "play", *rest]
    return argv
