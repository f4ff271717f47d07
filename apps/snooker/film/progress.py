"""The film's progress bar: frames done, frames a second, time left — on a terminal only."""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from typing import TextIO


class ProgressBar:
    def __init__(self, label: str, stream: TextIO | None = None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.label, self.stream, self.clock = label, stream or sys.stderr, clock
        self.start: float | None = None
        self.first = 0

    def __call__(self, done: int, total: int) -> None:
        now = self.clock()
        if self.start is None:  # frames already on disk do not count towards the rate
            self.start, self.first = now, done
        self.stream.write("\r" + self.line(done, total, now))
        if done >= total:
            self.stream.write("\n")
        self.stream.flush()

    def line(self, done: int, total: int, now: float) -> str:
        width = 30
        filled = width * done // max(total, 1)
        bar = "#" * filled + "." * (width - filled)
        spent = now - (self.start if self.start is not None else now)
        rate = (done - self.first) / spent if spent > 0 else 0.0
        left = f"{(total - done) / rate:.0f} s left" if rate > 0 else "-- s left"
        return f"{self.label} [{bar}] {done}/{total} {rate:.1f} frames/s {left}"


def progress_bar(label: str) -> ProgressBar | None:
    """A bar when stderr is a terminal; None (quiet) when it is a file or a pipe."""
    return ProgressBar(label) if sys.stderr.isatty() else None
