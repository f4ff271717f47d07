"""Drive the program with scripted input on an in-process Rainbow."""

from __future__ import annotations

from pathlib import Path

from camlab88.apps.snooker.program import script_events
from camlab88.apps.snooker.program.program import Program
from camlab88.apps.snooker.session import Session
from camlab88.apps.snooker.table import CUE

EMPTY = (300, 420)  # a cloth pixel with no ball (the opening position)


def feed(rb, program: Program, text: str) -> None:
    """Run a script (see script_events) to its end."""
    player = script_events.Player(script_events.parse(text, start=program.mouse or (0, 0)))
    while not player.finished:
        for e in player.due():
            rb.post(e)
        program.step()


def screen_colour(rb, x: int, y: int) -> tuple[int, int, int]:
    return tuple(int(v) for v in rb.executor.last_frame[y, x])


def hex_rgb(c: str) -> tuple[int, int, int]:
    return (int(c[1:3], 16), int(c[3:5], 16), int(c[5:7], 16))


def saved_game(path: Path, angle_deg: float) -> Session:
    """A new game, the cue ball struck at 1 m/s ``angle_deg`` degrees from up the table and
    run until every ball is at rest, saved to ``path``."""
    s = Session.new_game()
    s.strike(CUE, 1.0, angle_deg)
    s.simulate_to_rest()
    s.save(path)
    return s
