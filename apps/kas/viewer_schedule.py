"""The real-time line test's schedule (§2.3, §3.1.4), as a pure calculation.

§3.1.4: "the program keeps track of the elapsed time since the first frame of the sequence
was displayed in order to decide which frame should currently be on the screen".  So the
clock starts when frame 0 is shown (``clock="first-shown"``, the default): frame k is due at
``shown_0 + k/fps``.  After a frame is fully drawn into the hidden buffer it is shown
(buffers swapped) - but never before its own due time - and the program then sends the
frame due *now*, ``floor((now - shown_0) * fps)``, or the next frame if that one is already
on the screen.  Frames skipped over are dropped.  ``clock="first-sent"`` is the earlier
model, timed from the first transmitted character: it runs every due time early by frame
0's drawing time, so a slow first frame made the following ones look late and dropped.
With the frame sizes in characters and the line speed the whole run is determined.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Shown:
    frame: int
    send_start: float  # s: first character of the frame leaves the host
    drawn: float       # s: last character arrives at the terminal
    shown: float       # s: buffers swapped (>= the frame's due time)


@dataclass
class Schedule:
    shown: list[Shown] = field(default_factory=list)
    dropped: list[int] = field(default_factory=list)
    end: float = 0.0

    @property
    def shown_frames(self) -> list[int]:
        return [s.frame for s in self.shown]


def chars_per_second(baud: float = 9600, bits_per_char: float = 10.0) -> float:
    """9600 baud, 8 data bits, no parity, 1 stop bit (+1 start) = 960 characters a second."""
    return baud / bits_per_char


CLOCKS = ("first-shown", "first-sent")


def realtime(sizes: Sequence[int], fps: float = 25.0, baud: float = 9600,
             bits_per_char: float = 10.0, clock: str = "first-shown") -> Schedule:
    """Which frames the real-time viewer shows and drops; ``sizes`` = characters per frame
    (drawing orders plus the buffer swap); ``clock`` = when the elapsed time starts."""
    if fps <= 0 or baud <= 0:
        raise ValueError("fps and baud must be positive")
    if clock not in CLOCKS:
        raise ValueError(f"clock must be one of {', '.join(CLOCKS)}, not {clock!r}")
    cps = chars_per_second(baud, bits_per_char)
    sched = Schedule()
    t = 0.0
    origin = 0.0  # line time at which the elapsed-time clock reads 0
    last = -1
    n = len(sizes)
    while True:
        # A tiny tolerance so a frame finishing exactly on a period boundary counts as due.
        due = math.floor((t - origin) * fps + 1e-9)
        j = max(due, last + 1)
        if j >= n:
            break
        sched.dropped.extend(range(last + 1, j))
        drawn = t + sizes[j] / cps
        shown = max(drawn, origin + j / fps)
        if last < 0 and clock == "first-shown":
            origin = shown  # frame 0 is on the screen: the sequence's time starts now
        sched.shown.append(Shown(j, t, drawn, shown))
        last, t = j, shown
    sched.dropped.extend(range(last + 1, n))
    sched.end = t
    return sched


def every_frame(sizes: Sequence[int], baud: float = 9600,
                bits_per_char: float = 10.0) -> Schedule:
    """The other mode: every frame drawn and shown, however long it takes."""
    cps = chars_per_second(baud, bits_per_char)
    sched = Schedule()
    t = 0.0
    for j, size in enumerate(sizes):
        drawn = t + size / cps
        sched.shown.append(Shown(j, t, drawn, drawn))
        t = drawn
    sched.end = t
    return sched
