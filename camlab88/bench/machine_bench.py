"""What the two test benches share (docs/api.md): a machine from emulator.machine with a
protocol trace, whose screen, replies, problems and whole state a test reads the same way on
either device."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np

from camlab88.bench.traces import Trace


class MachineBench:
    """Base of ``camlab88.Sigma`` and ``camlab88.Rainbow``: ``machine`` is the device's
    machine (SigmaMachine, RainbowMachine), traced into ``.trace`` unless ``trace`` and
    ``strict`` are both off."""

    def __init__(self, machine: Any, trace: bool, strict: bool) -> None:
        self.machine = machine
        self.trace = Trace()
        if trace or strict:
            self.machine.trace(self.trace.add, strict)

    def received(self) -> bytes:
        """Device -> host: the bytes that have arrived at the host since the last call."""
        return self.machine.host.read()

    @property
    def screen(self) -> np.ndarray:
        """The screen as displayed: (height, width, 3) uint8, row 0 = top."""
        return self.machine.frame()

    def screenshot(self, path: str | os.PathLike[str]) -> Path:
        """Write the screen as a PNG (atomically); returns the path."""
        from camlab88.base.png import write_png

        return write_png(self.screen, path)

    @property
    def problems(self) -> list:
        """The first protocol problems (TraceEvent): warnings, refused commands; empty when
        the host did nothing wrong."""
        return list(self.trace.problems)

    def save_state(self) -> bytes:
        """The whole machine (clock, line or input queue, device), versioned."""
        return self.machine.save_state()

    def load_state(self, data: bytes) -> None:
        """Continue from save_state()'s bytes (ValueError if they do not fit this machine)."""
        self.machine.load_state(data)
