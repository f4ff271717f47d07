"""Generations computed ahead, checkpoints and a script's later interventions (pure model).

Section 7.3.2: "the program does not wait for this signal before performing the calculation
and drawing of the next generation, only before displaying it". With a display frequency
of N the look-ahead is N generations; checkpoints that fall inside it are kept and written
only when that state is shown (an edit may still discard it).

The look-ahead jumps: the engine's "auto" algorithm takes HashLife for long
stretches of deterministic rules, from checkpoint to checkpoint (a checkpoint after a jump
equals one after stepping).  Beyond the thesis: "Go to generation N" (a look-ahead of
N minus the shown generation, stopping where the script intervenes) and "Fast forward" (the
display frequency doubles with every generation shown).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from camlab88.apps.ca import log
from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.program.commands import ERROR, Ask, Dialogue
from camlab88.apps.ca.program.jump_bar import JumpBar, JumpStopped
from camlab88.apps.ca.session import Session

if TYPE_CHECKING:
    from camlab88.apps.ca.program.program import CAProgram

FAST_FORWARD_MAX = 1 << 24  # generations per shown frame at most while fast-forwarding


def ahead(session: Session, frequency: int, next_script: int | None,
          progress: Callable[[int], None] | None = None) -> tuple[Engine, list[Engine]]:
    """A copy of the shown state stepped ``frequency`` generations (stopping where the
    script intervenes next), and copies of the states due for a checkpoint on the way;
    ``progress(generation)`` is called as the engine goes."""
    engine = session.engine.copy()
    engine.algorithm = "auto"  # HashLife where it applies and pays
    steps = frequency
    if next_script is not None:
        steps = max(1, min(steps, next_script - engine.generation))
    every = session.checkpoint_every if session.writer is not None else 0
    target = engine.generation + steps
    due = []
    while engine.generation < target:
        n = target - engine.generation
        if every:
            n = min(n, every - engine.generation % every)  # stop at each checkpoint
        base = engine.generation
        engine.step(n, None if progress is None
                    else lambda done, _asked, base=base: progress(base + done))
        if every and engine.generation % every == 0 and engine.generation < target:
            due.append(engine.copy())
    return engine, due


def next_frequency(frequency: int, fast_forward: bool) -> int:
    """The display frequency after a generation is shown: doubled while fast-forwarding."""
    return min(2 * frequency, FAST_FORWARD_MAX) if fast_forward else frequency


def go_to_generation(p: CAProgram) -> Dialogue:
    """Ask for N and jump there, showing the state at N (checkpoints on the way written,
    the script's interventions applied where they fall)."""
    now = p.session.generation
    text = yield Ask("text", "Go to generation N =", default=str(now + 1000))
    if text is None:
        return
    try:
        target = int(text)
        if target < now:
            raise ValueError
    except ValueError:
        p.say(f"The generation must be a whole number from {now} on, not {text!r} (an "
              "earlier generation: replay the log with 'camlab88 ca replay')", ERROR)
        return
    bar = JumpBar(p, now, target, p.clock)
    try:
        while p.session.generation < target:
            p.pending, p.pending_checkpoints = ahead(p.session, target - p.session.generation,
                                                     p.script.next_generation, bar)
            p.display.buffers.back.stale = True  # drawn by commit, once
            p.commit()
    except JumpStopped:
        p.pending, p.pending_checkpoints = None, []
        p.say(f"Go to generation {target}: stopped at generation {p.session.generation}")
        return
    p.say(f"Generation {target}")


def fast_forward(p: CAProgram) -> Dialogue:
    """Run automatically, doubling the display frequency with every generation shown
    (Step mode, Auto mode or a new display frequency end it)."""
    if not p.fast_forward:
        p.frequency_before_fast_forward = p.frequency  # restored when it ends
    p.auto = True
    p.fast_forward = True
    p.main_menu.mark("Fast forward")
    p.say("Fast forward: each frame jumps twice as far as the last")
    return
    yield  # a dialogue with no questions


def end_fast_forward(p: CAProgram) -> None:
    """Stop doubling and go back to the display frequency in use before fast forward; the
    look-ahead already computed at the doubled frequency is dropped (recomputed at the
    restored one, so the next shown generation is frequency generations on, not 2**k)."""
    if not p.fast_forward:
        return
    p.fast_forward = False
    p.frequency = p.frequency_before_fast_forward
    p.pending = None
    p.pending_checkpoints = []


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
