"""Progress of a long jump, shown only once it has taken a while (so a jump that takes
seconds is not silent): a line such as ``generation 65536 of 100000 (66 %)``
rewritten in place on a terminal stream.  Wall-clock time decides only whether and when to
show it, never what the engine computes."""

from __future__ import annotations

import sys
import time
from typing import TextIO

SHOW_AFTER = 1.0  # seconds before the first line
EVERY = 0.25  # seconds between lines


class ProgressLine:
    """A ``progress(done, asked)`` callback for Engine.step that writes to ``stream``."""

    def __init__(self, stream: TextIO | None = None, start_generation: int = 0,
                 clock=time.monotonic) -> None:  # a clock function
        self.stream = stream if stream is not None else sys.stderr
        self.start_generation = start_generation
        self.clock = clock
        self.started = clock()
        self.last = None  # when the last line was written
        self.shown = False

    def __call__(self, done: int, asked: int) -> None:
        now = self.clock()
        if now - self.started < SHOW_AFTER or (self.last is not None
                                               and now - self.last < EVERY and done < asked):
            return
        self.last = now
        self.shown = True
        end = "\r" if done < asked and self.stream.isatty() else "\n"
        self.stream.write(f"generation {self.start_generation + done} of "
                          f"{self.start_generation + asked} ({100 * done // max(asked, 1)} %)"
                          f"{end}")
        self.stream.flush()
