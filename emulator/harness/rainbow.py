"""The harness target for a program on an in-process Rainbow (snooker, CA, the Rainbow demo,
and new Rainbow programs).  One tick = one program step, normally one 1/50 s display frame.
"""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction
from typing import Any

import numpy as np
from camlab88.emulator.harness.program_state import SavesState
from camlab88.emulator.host_input import HostEvent
from camlab88.emulator.rainbow.host_input import RainbowHostInput
from camlab88.protocols.rainbow.script import Player

FPS = 50  # the Rainbow's display frames per second


class RainbowTarget(SavesState):
    """``step()`` advances the program (True while it runs).  Window input goes to the
    device's input controller; with a ``script`` (protocols.rainbow.script.Player) the
    script drives the mouse and keyboard instead (and, with ``end_with_script``, the run
    ends with it; in a window the program carries on until it is closed)."""

    fps = FPS
    size = (768, 576)
    escape_is_a_key = False  # True where the program reads Esc itself (the harness: quit)
    _state_exclude = ("on_input",)  # a replay's listener: kept as set, never saved

    def __init__(self, session: Any, step: Callable[[], bool], title: str, keys: str,
                 script: Player | None = None, end_with_script: bool = True,
                 status: Callable[[], str] | None = None) -> None:
        self.session = session
        self.step = step
        self.title = title
        self.keys = keys
        self.script = script
        self.end_with_script = end_with_script
        if status is not None:  # the harness's optional title-bar status
            self.status = status
        self.host = RainbowHostInput()
        self._wire_at = 0
        self.tablet: Any = None  # a tablet source the command polls in its step
        self.on_input: Callable[[Any], None] | None = None  # told each scripted event


    def handle_events(self, events: list[HostEvent]) -> None:
        if self.script is not None and not self.script.finished:
            for e in self.script.due():
                self.session.inject(e)
                if self.on_input is not None:
                    self.on_input(e)
            return  # the window's input counts once the script has played
        for ev in events:
            dev = self.host.convert(ev)
            if dev is not None:
                self.session.inject(dev)

    def tick(self) -> bool:
        alive = bool(self.step())
        ended = self.script is not None and self.end_with_script and self.script.finished
        return alive and not ended

    def frame(self) -> np.ndarray:
        last = self.session.executor.last_frame
        return last if last is not None else self.session.device.peek()

    def time(self) -> Fraction:
        return Fraction(self.session.device.frame_count, FPS)

    def wire(self) -> list[tuple[str, bytes]]:
        """The command stream since the last call (sessions made with ``record=True``)."""
        rec = getattr(self.session.recorder, "recording", None)
        if rec is None:
            return []
        new = rec.entries[self._wire_at:]
        self._wire_at = len(rec.entries)
        out = [(d, data) for d, data in new if d in "><"]
        take_tape = getattr(self.tablet, "take_tape", None)  # a --tablet on tape (recording)
        if take_tape is not None:
            out.append(("T", take_tape()))
        return out
