"""What the tablet tools (emulate, monitor, calibrate) share as programs on the harness
(emulator.harness): a tick is a 60th of a second of the tablet's life; the frame is the
emulated tablet's view, if there is one, and the window's events go to it.  A real tablet
runs the same program headless, its reads pacing the ticks."""

from __future__ import annotations

from abc import ABC, abstractmethod
from fractions import Fraction
from typing import Any

import numpy as np

FPS = 60


class TabletProgram(ABC):
    """A harness target around an optional emulated tablet; subclasses define ``step``."""

    fps = float(FPS)
    exit_status = 0  # the command's exit status once the run ends

    def __init__(self, emu: Any, keys: str) -> None:
        self.emu = emu
        self.keys = keys
        self.title = emu.title if emu is not None else "camlab88 tablet"
        view = getattr(emu, "view", None)
        self.size = view.size if view is not None else (1, 1)
        self.ticks = 0

    def time(self) -> Fraction:
        return Fraction(self.ticks, FPS)

    def handle_events(self, events: list) -> None:
        if self.emu is not None:
            self.emu.handle(events)

    def tick(self) -> bool:
        self.ticks += 1
        return self.step()

    @abstractmethod
    def step(self) -> bool:
        """One tick of the tool; False ends the run."""

    def frame(self) -> np.ndarray:
        if self.emu is None:
            return np.zeros((1, 1, 3), dtype=np.uint8)
        return self.emu.frame()

