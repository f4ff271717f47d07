"""The harness target for a host program on a Sigma machine: the program talks to the
machine's port, the target runs the machine.  Each tick the program takes its turn
(``step() -> bool``: False when it has finished and the run ends), then the machine runs
``dt`` of line time -- or, with ``dt=None``, until the line is quiet, so one tick is one
whole exchange and line time jumps -- and ``done()`` (optional) may end the run.

Window input reaches the program as what a host sees of its user's hand: ``pointer(x, y)``
(device pixels, y up), ``click()`` (left button pressed) and ``key(name, shift)``, each only
if the program has it (e.g. the painting program, whose user points with a mouse)."""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction
from typing import Any

import numpy as np

from camlab88.emulator.harness import input_log
from camlab88.emulator.harness.sigma_batch import settle
from camlab88.emulator.host_input import HostEvent, KeyDown, PointerButton, PointerMove
from camlab88.emulator.machine import SigmaMachine


class SigmaHostTarget:
    size = (768, 512)
    snapshots_by_graph = True  # F4 in memory: a declared state is rebuilt from the start

    def __init__(self, machine: SigmaMachine, program: Any, title: str, keys: str,
                 dt: Fraction | None = Fraction(1, 25), fps: int = 25,
                 on_tick: Callable[[np.ndarray], None] | None = None) -> None:
        self.machine, self.program = machine, program
        self.title, self.keys = title, keys
        self.dt, self.fps, self.on_tick = dt, fps, on_tick
        self.log = input_log.InputLog()

    @property
    def on_input(self) -> Callable[[Any], None] | None:
        """A listener told each scripted input the program takes (a program that plays a
        script has an ``on_input`` of its own: the web replay's timeline)."""
        return getattr(self.program, "on_input", None)

    @on_input.setter
    def on_input(self, listener: Callable[[Any], None] | None) -> None:
        if hasattr(self.program, "on_input"):
            self.program.on_input = listener

    def handle_events(self, events: list[HostEvent]) -> None:
        p = self.program
        self.log.given(events)
        for ev in events:
            if isinstance(ev, PointerMove | PointerButton) and hasattr(p, "pointer"):
                p.pointer(ev.x, self.size[1] - 1 - ev.y)
            if isinstance(ev, PointerButton) and ev.pressed and ev.button == 1:
                if hasattr(p, "click"):
                    p.click()
            elif isinstance(ev, KeyDown) and hasattr(p, "key"):
                p.key(ev.key, "shift" in ev.mods)

    def tick(self) -> bool:
        self.log.ticked()
        if not self.program.step():
            return False
        if self.dt is None:
            settle(self.machine)
        else:
            self.machine.tick(self.dt)
        if self.on_tick is not None:
            self.on_tick(self.machine.frame())
        done = getattr(self.program, "done", None)
        return not (done is not None and done())

    def frame(self) -> np.ndarray:
        return self.machine.frame()

    # its declared state (program_state): the input that made it (emulator.harness.
    # input_log); a load runs the fresh program again with it (kas paint writes only at
    # the end of its run, so nothing needs holding back). Version 2: the log's ``tablet``
    # (always none here: the painting program takes no tablet); migrate_state reads 1
    STATE_VERSION = input_log.VERSION_WITH_TABLET
    STATE_SCHEMA = input_log.SCHEMA

    @staticmethod
    def migrate_state(version: int, values: Any) -> Any:
        return input_log.migrate_values(version, values, has_start=False)

    def picture(self) -> str:
        return input_log.picture_hash(self.frame(), self.machine.save_state())

    def state_values(self) -> dict[str, Any]:
        return self.log.values(self.picture())

    def load_state_values(self, values: dict[str, Any]) -> None:
        self.log.rebuild(values, self.handle_events, self.tick, lambda: None, self.picture)

    def time(self) -> Fraction:
        return self.machine.now

    def status(self) -> str:
        """The window's title bar: what the program says of itself, the line time, the keys."""
        said = getattr(self.program, "status", None)
        head = f"{said()}, " if said is not None else ""
        return f"{head}line time {float(self.time()):.1f} s | {self.keys}"
