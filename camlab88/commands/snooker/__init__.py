"""``camlab88 snooker ...``: the snooker motion-development program (thesis ch. 6).

``camlab88 snooker [SESSION]`` with no action is ``snooker play [SESSION]``.
"""

from __future__ import annotations

import argparse

from camlab88.argtypes import dask_address

ACTIONS = ("play", "simulate", "replay", "ccl", "visualise", "camera", "render", "film")
HELP = """\
snooker motion development (thesis chapter 6): `camlab88 snooker [SESSION]` runs the \
interactive program (= `snooker play`); simulate shots; replay checkpoint files"""


def add_looks_options(p: argparse.ArgumentParser) -> None:
    """The looks options several of the area's commands share."""
    p.add_argument("--no-specks", action="store_true", help="leave out the dust specks")
    p.add_argument("--no-wood", action="store_true",
                   help="truecolour: constant-shaded wood, as the Sigma modes draw it")


def add_dask_options(p: argparse.ArgumentParser) -> None:
    """The dask options several of the area's commands share."""
    p.add_argument("--dask", type=dask_address, metavar="ADDRESS|local",
                   help="render on a Dask cluster (a scheduler address, or 'local')")



def normalise_argv(argv: list[str]) -> list[str]:
    """``camlab88 snooker [SESSION] [options]`` is the interactive program: with no
    action named, insert ``play`` so the session file and options reach it."""
    if argv[:1] == ["snooker"]:
        rest = argv[1:]
        if not rest or rest[0] not in (*ACTIONS, "-h", "--help"):
            return ["snooker", "play", *rest]
    return argv
