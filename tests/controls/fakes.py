"""A wall clock and a window for testing the controls without sleeping or a display."""

from __future__ import annotations

import numpy as np


class FakeClock:
    """``monotonic`` reads ``now``; ``sleep`` moves it on and keeps the total."""

    def __init__(self) -> None:
        self.now = 100.0
        self.slept: list[float] = []

    def monotonic(self) -> float:
        return self.now

    def sleep(self, s: float) -> None:
        self.slept.append(s)
        self.now += s


class FakeWindow:
    """Scripted input: ``script[k]`` is what the k-th poll returns (then nothing).  Keeps
    every picture shown (after the controls' decoration) and every caption."""

    def __init__(self, script: dict[int, list] | None = None) -> None:
        self.script = script or {}
        self.polls = 0
        self.shown: list[np.ndarray] = []
        self.captions: list[str] = []
        self.decorate = None
        self.closed = False

    def poll(self) -> list:
        if self.polls > 10_000:  # a pause that never ends fails, never hangs the test
            raise AssertionError("still polling after 10000 polls: the run never went on")
        events = self.script.get(self.polls, [])
        self.polls += 1
        return list(events)

    def show(self, frame: np.ndarray) -> None:
        self.shown.append(self.decorate(frame) if self.decorate else frame)

    def set_caption(self, text: str) -> None:
        self.captions.append(text)

    def close(self) -> None:
        self.closed = True


def harness_with(target, window: FakeWindow | None, clock: FakeClock, **controls):
    """A Harness whose window is ``window`` (the run is headless otherwise), on ``clock``."""
    from camlab88.emulator.harness import Harness, RunOptions
    from camlab88.emulator.harness.control_options import Controls

    c = Controls(monotonic=clock.monotonic, sleep=clock.sleep, **controls)
    h = Harness(target, RunOptions(controls=c))
    h.window = window
    return h
