"""Generations computed ahead, checkpoints and a script's later interventions (pure model).

Section 7.3.2: "the program does not wait for this signal before performing the calculation
and drawing of the next generation, only before displaying it". With a display frequency
of N the look-ahead is N generations; checkpoints that fall inside it are kept and written
only when that state is shown (an edit may still discard it).
"""

from __future__ import annotations

from apps.ca import log
from apps.ca.engine import Engine
from apps.ca.session import Session


def ahead(session: Session, frequency: int, next_script: int | None) -> tuple[Engine,
                                                                               list[Engine]]:
    """A copy of the shown state stepped ``frequency`` generations (stopping where the
    script intervenes next), and copies of the states due for a checkpoint on the way."""
    engine = session.engine.copy()
    steps = frequency
    if next_script is not None:
        steps = max(1, min(steps, next_script - engine.generation))
    every = session.checkpoint_every if session.writer is not None else 0
    due = []
    for i in range(steps):
        engine.step()
        if every and engine.generation % every == 0 and i < steps - 1:
            due.append(engine.copy())
    return engine, due


def write_checkpoints(session: Session, passed: list[Engine]) -> None:
    """Checkpoints of the generations passed on the way and of the one now shown."""
    w = session.writer
    every = session.checkpoint_every
    if w is None or not every:
        return
    for e in passed:
        log.write_checkpoint(w.path, e)
    if session.generation % every == 0:
        log.write_checkpoint(w.path, session.engine)


class ScriptFeed:
    """A script's interventions after the generation it was begun at, in order."""

    def __init__(self, events: list[log.Event] | None = None) -> None:
        self.queue = list(events or [])

    @property
    def next_generation(self) -> int | None:
        return self.queue[0].generation if self.queue else None

    def due(self, generation: int) -> list[log.Event]:
        out = [e for e in self.queue if e.generation <= generation]
        self.queue = [e for e in self.queue if e.generation > generation]
        return out
