"""What the emulator controls were asked for on the command line (``--speed``, ``--video``,
``--inspect``, ``--inspect-out``); one field of :class:`camlab88.emulator.harness.RunOptions`."""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

SPEED_MIN, SPEED_MAX = 0.1, 1000.0


@dataclass
class Controls:
    """``speed``: wall-clock pacing, 1 = period speed, None = as the run decides (a window
    at period speed, headless flat out).  ``video``: an .mp4/.gif of the frames shown.
    ``inspect``: the inspector panel beside the screen in the window; ``inspect_out``: the
    same panels as DIR/frame_NNNNN.png, one per frame shown.  ``shots``: where the F12
    screenshot key writes.  ``monotonic``/``sleep``: the wall clock (a test injects its own)."""

    speed: float | None = None
    video: Path | None = None
    inspect: bool = False
    inspect_out: Path | None = None
    shots: Path | None = None
    monotonic: Callable[[], float] = time.monotonic
    sleep: Callable[[float], None] = time.sleep


def clamp_speed(speed: float) -> float:
    """A speed inside the range the controls accept."""
    return min(SPEED_MAX, max(SPEED_MIN, speed))
