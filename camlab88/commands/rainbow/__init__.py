"""``camlab88 rainbow ...``: render a scene file; run, serve or replay the emulator."""

from __future__ import annotations

import argparse

from camlab88.replay_policy import KEEP

ACTIONS = ("render", "run", "serve", "replay")
HELP = "the Rainbow workstation emulator"
DESCRIPTION = """\
The Cambridge Rainbow workstation: pads, clusters, band structure, video processor."""
__all__ = ["ACTIONS", "register"]


def add_relic_memory_options(p: argparse.ArgumentParser) -> None:
    """The relic_memory options several of the area's commands share."""
    p.add_argument("--strict", action="store_true",
                   help="the relic's video memory (64K 16-bit words)").replay = KEEP

