"""The ``--events FILE`` option of the interactive programs on the emulated Rainbow (snooker
play, snooker camera, ca program): scripted mouse and keyboard input, one language for all
(protocols/rainbow/script.py, docs/harness.md)."""

from __future__ import annotations

import argparse

HEADLESS_NEEDS_EVENTS = ("Headless it needs --events (the run ends with the script) or "
                         "--stop-after N.")


def add_events_option(p: argparse.ArgumentParser) -> None:
    p.add_argument("--events", metavar="FILE",
                   help="scripted mouse/keyboard input (the Rainbow script format, "
                   "docs/harness.md: move, glide, press, release, click, drag, key, type, wait)")
