"""A harness target for tests of the loop and the controls, with no device behind it."""

from __future__ import annotations

from fractions import Fraction

import numpy as np


class Counter:
    """A target counting ticks of 1/50 s to ``n``: frame k is k in every pixel (25 fps shown,
    two ticks a frame); ``closable=False`` refuses a window close as unsaved work would."""

    title, keys, fps = "counter", "a: a key; b: another", 25

    def __init__(self, n: int, size: tuple[int, int] = (4, 3), closable: bool = True) -> None:
        self.n, self.t, self.size, self.closable = n, 0, size, closable
        self.got: list[object] = []

    def handle_events(self, events: list) -> None:
        self.got += events

    def tick(self) -> bool:
        self.t += 1
        return self.t < self.n

    def frame(self) -> np.ndarray:
        w, h = self.size
        return np.full((h, w, 3), self.t % 256, np.uint8)

    def time(self) -> Fraction:
        return Fraction(self.t, 50)

    def may_close(self) -> bool:
        return self.closable
