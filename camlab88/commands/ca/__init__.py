"""``camlab88 ca ...``: the programmable cellular automaton of thesis chapter 7."""

from __future__ import annotations

import argparse

from camlab88.areas import register_area

HELP = "the programmable cellular automaton (chapter 7)"
ACTIONS = ("run", "convert", "replay", "library", "program")


def register(subparsers: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    register_area(subparsers, __name__, "ca", HELP, ACTIONS,
                  "The programmable cellular automaton of thesis chapter 7: rule files, "
                  "patterns, logs and scripts.")


def run_demo(headless: bool = True, screenshot: str | None = None, scale: int = 1,
             generations: int = 60) -> dict:
    """The demo act's CA session (Life's Gosper gun in auto mode, panned and zoomed) run
    headless; returns the final statistics.  Kept for callers of the old name."""
    from apps.ca.program.demo import demo_events
    from apps.ca.program.program import CAProgram, Options
    from apps.ca.program.script_events import parse, play
    from emulator.rainbow.session import in_process
    from protocols.png import write_png

    session = in_process()
    program = CAProgram(session.client, Options(rules="life", pattern="gosper_gun"))
    play(parse(demo_events(generations), "<ca demo>"), session.inject, program.frame,
         lambda: program.finished)
    if screenshot:
        write_png(session.executor.last_frame, screenshot)
    return program.session.statistics()
