"""``--record FILE``: the harness plugin that writes a session recording (protocols.session).

Generic: any target the harness runs gets it.  It stores the command line, every argument
that names an existing file (by content, so a later edit of the input does not change the
replay), every host input event at its tick and virtual time, the target's wire traffic
(``target.wire()``, when it has one), a screen hash every ``hash_every`` frames and at the end.
"""

from __future__ import annotations

import hashlib
import sys
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from camlab88.emulator.harness import codec
from camlab88.emulator.harness.loop import Plugin, RunOptions
from camlab88.emulator.host_input import HostEvent
from camlab88.protocols.session import ScreenHash
from camlab88.protocols.session.writer import SessionWriter

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness

HASH_EVERY = 10
_OPTIONS_NOT_RECORDED = {"--record"}  # value options the replay must not repeat


def shown(harness: Harness) -> np.ndarray:
    """The frame last shown, or the screen as it stands before any."""
    return harness.last_frame if harness.last_frame is not None else harness.screen()


def screen_hash(frame: np.ndarray) -> str:
    """SHA-256 of a frame's shape and RGB bytes (row 0 = top)."""
    arr = np.ascontiguousarray(frame, dtype=np.uint8)
    h = hashlib.sha256(f"{arr.shape[0]}x{arr.shape[1]}:".encode())
    h.update(arr.tobytes())
    return h.hexdigest()


def replay_argv(argv: list[str]) -> list[str]:
    """``argv`` without ``--record FILE`` (or ``--record=FILE``)."""
    out: list[str] = []
    skip = False
    for a in argv:
        if skip:
            skip = False
        elif a in _OPTIONS_NOT_RECORDED:
            skip = True
        elif a.split("=", 1)[0] not in _OPTIONS_NOT_RECORDED:
            out.append(a)
    return out


def input_files(argv: list[str], extra: list[Path]) -> dict[str, bytes]:
    """Every argument naming an existing file, and ``extra``, by content."""
    files: dict[str, bytes] = {}
    for a in [*argv, *map(str, extra)]:
        value = a.split("=", 1)[1] if a.startswith("--") and "=" in a else a
        p = Path(value)
        if value and p.is_file():
            files[value] = p.read_bytes()
    return files


class SessionRecorder(Plugin):
    """Writes the session as it runs (protocols.session.writer: to a temporary file beside
    the target, renamed into place when the run ends), so its memory does not grow with the
    session's length."""

    def __init__(self, options: RunOptions) -> None:
        self.path = Path(options.record)
        argv = replay_argv(options.argv)
        self.out = SessionWriter(self.path, argv, HASH_EVERY, options.headless,
                                 input_files(argv, options.inputs))
        self._pending: dict[str, bytearray] = {}

    def start(self, harness: Harness) -> None:
        if harness.frames_shown > 0:  # begun from --load-state (loaded by now): its screen
            self.out.hash(ScreenHash(harness.frames_shown, harness.ticks,  # bounds the reader
                                     harness.target.time(), screen_hash(shown(harness))))

    def handle_events(self, harness: Harness, events: list[HostEvent]) -> list[HostEvent]:
        t = harness.target.time()
        for e in events:
            self.out.event(harness.ticks, t, codec.encode(e))
        return events

    def post_tick(self, harness: Harness) -> None:
        wire = getattr(harness.target, "wire", None)
        if wire is None:
            return
        for d, data in wire():
            # outside input, a client leaving, a tablet tape: at its tick, for the replay
            if (d in "+T" and data) or d == "-":
                self.out.wire(harness.ticks, d, data)
            elif data:
                self._pending.setdefault(d, bytearray()).extend(data)

    def _flush_wire(self, tick: int) -> None:
        """The program/device traffic since the last flush, one record a direction (one
        record a tick would cost more in JSON than the bytes themselves)."""
        for d, data in sorted(self._pending.items()):
            if data:
                self.out.wire(tick, d, bytes(data))
        self._pending = {}

    def wants_frame(self, harness: Harness) -> bool:
        return harness.frames_shown % HASH_EVERY == 0

    def on_frame(self, harness: Harness, frame: np.ndarray | None) -> None:
        n = harness.frames_shown
        if n % HASH_EVERY == 0 and frame is not None:
            self._flush_wire(harness.ticks)
            self.out.hash(ScreenHash(n, harness.ticks, harness.target.time(),
                                     screen_hash(frame)))

    def finish(self, harness: Harness) -> None:
        try:
            self._flush_wire(harness.ticks)
            self.out.finish(ScreenHash(harness.frames_shown, harness.ticks,
                                       harness.target.time(), screen_hash(shown(harness))),
                            harness.ticks)
        except BaseException:  # no recording: the half-written file goes, an older one stays
            self.out.abandon()
            raise
        print(f"{harness.options.command}: recorded the session to {self.path} "
              f"({self.out.events} input events, {self.out.hashes + 1} screen "
              f"hashes)", file=sys.stderr)
