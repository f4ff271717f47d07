"""The progress bar of a long "Go to generation" jump, and Escape to stop it.

The jump runs inside one dialogue step, so the frame loop does not read input meanwhile:
the engine's progress callback (after each HashLife jump, or each direct generation) does.
Once the jump has taken SHOW_AFTER seconds it shows a bar on the prompt line every EVERY
seconds and lets the device show a frame; Escape in the input queue stops the jump (the
state already shown stays; nothing computed after it is kept), other input is held for
the frame loop: at most HOLD_LIMIT events, the oldest dropped first, as the Rainbow's own
input queue drops what a program does not read (a state holds them: apps/ca/program/
state.py). Wall-clock time decides only when the bar is drawn and input read, never what
the engine computes.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TYPE_CHECKING

from camlab88.protocols.rainbow.events import KeyEvent

if TYPE_CHECKING:
    from camlab88.apps.ca.program.program import CAProgram

SHOW_AFTER = 1.0  # seconds before the bar first appears
EVERY = 0.25  # seconds between redraws
WIDTH = 40  # characters of bar
POLL_LIMIT = 256
# input held for the frame loop during one jump: as many as the Rainbow's input queue keeps
# (emulator/rainbow/inputs.py QUEUE_LIMIT), so a long jump holds no more than the device would
HOLD_LIMIT = 4096
COLOUR = "#fff0a0"  # the prompt line's colour for questions (program.PROMPT)


class JumpStopped(Exception):
    """Escape was pressed during a jump."""


class JumpBar:
    """``bar(generation)``: the jump towards ``target`` has reached ``generation``."""

    def __init__(self, p: CAProgram, start: int, target: int,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.p, self.start, self.target, self.clock = p, start, target, clock
        self.started = clock()
        self.last: float | None = None
        self.shown = False

    def text(self, generation: int) -> str:
        done = (generation - self.start) / max(1, self.target - self.start)
        fill = int(WIDTH * done)
        return (f"Go to generation {self.target}: generation {generation}\n"
                f"[{'#' * fill}{'.' * (WIDTH - fill)}] {int(100 * done)} %   Escape stops")

    def __call__(self, generation: int) -> None:
        now = self.clock()
        if now - self.started < SHOW_AFTER or (self.last is not None
                                               and now - self.last < EVERY):
            return
        self.last = now
        self._read_input()
        self.shown = True
        self.p.say(self.text(generation), COLOUR)
        self.p.client.wait_frame()  # let the device show it

    def _read_input(self) -> None:
        for e in self.p.client.drain_events(POLL_LIMIT):
            if isinstance(e, KeyEvent) and e.pressed and e.key == "escape":
                raise JumpStopped
            self.p.held_events.append(e)
        del self.p.held_events[:-HOLD_LIMIT]
