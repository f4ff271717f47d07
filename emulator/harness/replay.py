"""Replaying a session recording through the harness.

``camlab88 replay`` re-runs the recorded command inside :func:`replaying`; while that context
is active, every harness the command builds takes its input from the recording (not the
window), feeds recorded outside wire bytes back to the target (``target.put_wire``), ignores
``--record``, takes ``--headless`` / ``--period`` / ``--frames`` / ``--screenshot`` from the
replay, and (with ``check``) compares every screen hash, stopping at the first difference.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from camlab88.emulator.harness import codec
from camlab88.emulator.harness.control_options import Controls
from camlab88.emulator.harness.loop import Plugin, RunOptions
from camlab88.emulator.harness.replay_window import RecordWindow
from camlab88.emulator.harness.session_record import screen_hash, shown
from camlab88.emulator.host_input import HostEvent, Quit
from camlab88.protocols.session import ScreenHash, SessionRecording

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness


@dataclass(frozen=True)
class Mismatch:
    """The first screen that differs from the recording."""

    frame: int
    tick: int
    time: Fraction
    expected: str
    got: str

    def describe(self) -> str:
        want, got = _short(self.expected, self.got), _short(self.got, self.expected)
        return (f"frame {self.frame} (tick {self.tick}, t = {float(self.time):.3f} s) differs "
                f"from the recording: expected {want}, got {got}")


def _short(text: str, other: str) -> str:
    """A hash cut to 16 digits, or as many more as it takes to differ from ``other``."""
    if len(text) != 64:
        return text
    same = next((i for i, (a, b) in enumerate(zip(text, other, strict=False)) if a != b), 64)
    return text[:max(16, same + 4)]


@dataclass
class Replay:
    """An active replay: the recording and what the replay was asked to do."""

    rec: SessionRecording
    headless: bool = True
    period: bool = False
    check: bool = False
    frames: Path | None = None
    screenshot: Path | None = None
    mismatch: Mismatch | None = None
    compared: int = 0
    runs: int = 0
    ended: ScreenHash | None = field(default=None)
    controls: Controls | None = None  # the replay's --speed, --video, --inspect...
    state: Any = None       # the replay's StateOptions (--seek, --save-state, --load-state)
    seeking: bool = False   # a seek's first run: it stops at the seek time, not the end
    wrote: list[str] = field(default_factory=list)  # what the run's writers named (written.py)
    capture: Plugin | None = None  # --html: gathers the web page's video, events and orders
    fault: str | None = None  # the recording could not be read again (RecordWindow.fault)

    def adjust(self, options: RunOptions) -> None:
        options.headless = self.headless
        options.paced = options.realtime = self.period
        options.frames, options.screenshot, options.record = self.frames, self.screenshot, None
        options.stop_after = None  # the recording's events and end decide
        # the replay's controls, not the recorded run's (--period is --speed 1)
        options.controls = self.controls or Controls(speed=1.0 if self.period else None)
        self.runs += 1

    def plugins(self) -> list[Plugin]:
        extra = [self.capture] if self.capture is not None else []
        window = RecordWindow(self.rec, self.check)  # one reading of it for each run
        return [RecordedInput(self, window), HashCheck(self, window), *extra]


_ACTIVE: ContextVar[Replay | None] = ContextVar("camlab88_replay", default=None)


def active() -> Replay | None:
    """The replay in progress, or None (a command asks before opening e.g. a pty)."""
    return _ACTIVE.get()


@contextmanager
def replaying(replay: Replay) -> Iterator[Replay]:
    token = _ACTIVE.set(replay)
    try:
        yield replay
    finally:
        _ACTIVE.reset(token)


class RecordedInput(Plugin):
    """The recording's events at their ticks instead of the window's (a window close still
    stops the replay); outside wire bytes back to the target; stop at the recorded end.
    Both come from a RecordWindow: the recording is read as the run goes, not held."""

    def __init__(self, replay: Replay, window: RecordWindow) -> None:
        rec = replay.rec
        self.replay, self.window = replay, window
        self.end_tick = rec.ticks
        self.end_frame = rec.end.frame if rec.end is not None else None

    def handle_events(self, harness: Harness, events: list[HostEvent]) -> list[HostEvent]:
        put = getattr(harness.target, "put_wire", None)
        hang_up = getattr(harness.target, "put_hang_up", None)
        for d, data in self.window.wire_at(harness.ticks):  # recorded after: fed before
            if d == "+" and put is not None:
                put(data)
            elif d == "-" and hang_up is not None:
                hang_up()
        window_quit = [e for e in events if isinstance(e, Quit)]
        recorded = [codec.decode(obj) for obj in self.window.events_at(harness.ticks)]
        if self.window.fault is not None:  # the file changed under the replay
            self.replay.fault = self.window.fault
        if self.replay.fault is not None:  # ... or its tablet tape could not be read on
            harness.stop()
        return recorded + window_quit

    def post_tick(self, harness: Harness) -> None:
        past = self.end_frame is not None and harness.frames_shown > self.end_frame
        if harness.ticks >= self.end_tick or past:  # past the recorded end: it differs
            harness.stop()

    def finish(self, harness: Harness) -> None:
        self.window.close()


class HashCheck(Plugin):
    """With ``check``: compare each recorded screen hash; the first difference stops the run."""

    def __init__(self, replay: Replay, window: RecordWindow) -> None:
        self.replay, self.window = replay, window
        rec = replay.rec
        self.every = rec.hash_every
        # the recorder hashes every multiple of hash_every up to the end (the reader checks)
        self.last = (rec.end.frame // self.every * self.every if rec.end is not None
                     else max((h.frame for h in rec.hashes), default=0))

    def start(self, harness: Harness) -> None:
        """A run begun from --load-state (loaded by now): its first frame, the state's (not
        a seek's snapshot: that is taken at a time between two frames)."""
        seek_snapshot = getattr(self.replay.state, "load_data", None) is not None
        if self.replay.check and harness.frames_shown > 0 and not seek_snapshot:
            want = self.window.hash_at(harness.frames_shown)
            if want is not None:
                self._compare(harness, want, shown(harness))

    def wants_frame(self, harness: Harness) -> bool:
        n = harness.frames_shown
        return self.replay.check and 0 < n <= self.last and n % self.every == 0

    def on_frame(self, harness: Harness, frame: np.ndarray | None) -> None:
        if not self.wants_frame(harness) or self.replay.mismatch is not None or frame is None:
            return
        want = self.window.hash_at(harness.frames_shown)  # compared as it comes, then dropped
        if want is not None:
            self._compare(harness, want, frame)
        elif self.window.fault is not None:
            self.replay.fault = self.window.fault
            harness.stop()

    def _compare(self, harness: Harness, want: ScreenHash, frame: np.ndarray) -> None:
        got = screen_hash(frame)
        self.replay.compared += 1
        now = harness.target.time()
        if (harness.ticks, now) != (want.tick, want.time):  # an altered tick or time
            self.replay.mismatch = Mismatch(want.frame, harness.ticks, now,
                                            _when(want.tick, want.time),
                                            _when(harness.ticks, now))
        elif got != want.sha256:
            self.replay.mismatch = Mismatch(want.frame, harness.ticks, now, want.sha256, got)
        if self.replay.mismatch is not None:
            harness.stop()

    def finish(self, harness: Harness) -> None:
        end = self.replay.rec.end
        self.replay.ended = ScreenHash(harness.frames_shown, harness.ticks,
                                       harness.target.time(), screen_hash(shown(harness)))
        if (not self.replay.check or self.replay.mismatch is not None or end is None
                or self.replay.seeking):
            return
        if (harness.frames_shown, harness.ticks, harness.target.time()) != \
                (end.frame, end.tick, end.time):
            self.replay.mismatch = Mismatch(
                min(end.frame, harness.frames_shown), harness.ticks, harness.target.time(),
                f"the end at frame {end.frame}, {_when(end.tick, end.time)}",
                f"the end at frame {harness.frames_shown}, "
                f"{_when(harness.ticks, harness.target.time())}")
            return
        self.replay.compared += 1
        got = self.replay.ended.sha256
        if got != end.sha256:
            self.replay.mismatch = Mismatch(end.frame, end.tick, end.time, end.sha256, got)


def _when(tick: int, time: Fraction) -> str:
    return f"tick {tick}, time {time} s"
