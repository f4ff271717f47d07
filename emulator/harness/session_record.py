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
from camlab88.protocols.session import ScreenHash, SessionRecording, write

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness

HASH_EVERY = 10
_OPTIONS_NOT_RECORDED = {"--record"}  # value options the replay must not repeat


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
    """Collects the session while it runs and writes it when the run ends."""

    def __init__(self, options: RunOptions) -> None:
        self.path = Path(options.record)
        argv = replay_argv(options.argv)
        self.rec = SessionRecording(argv, HASH_EVERY, options.headless,
                                    input_files(argv, options.inputs))
        self._pending: dict[str, bytearray] = {}

    def handle_events(self, harness: Harness, events: list[HostEvent]) -> list[HostEvent]:
        t = harness.target.time()
        self.rec.events += [(harness.ticks, t, codec.encode(e)) for e in events]
        return events

    def post_tick(self, harness: Harness) -> None:
        wire = getattr(harness.target, "wire", None)
        if wire is None:
            return
        for d, data in wire():
            # outside input, a client leaving, a tablet tape: at its tick, for the replay
            if (d in "+T" and data) or d == "-":
                self.rec.wire.append((harness.ticks, d, data))
            elif data:
                self._pending.setdefault(d, bytearray()).extend(data)

    def _flush_wire(self, tick: int) -> None:
        """The program/device traffic since the last flush, one record a direction (one
        record a tick would cost more in JSON than the bytes themselves)."""
        for d, data in sorted(self._pending.items()):
            if data:
                self.rec.wire.append((tick, d, bytes(data)))
        self._pending = {}

    def wants_frame(self, harness: Harness) -> bool:
        return harness.frames_shown % HASH_EVERY == 0

    def on_frame(self, harness: Harness, frame: np.ndarray | None) -> None:
        n = harness.frames_shown
        if n % HASH_EVERY == 0 and frame is not None:
            self._flush_wire(harness.ticks)
            self.rec.hashes.append(ScreenHash(n, harness.ticks, harness.target.time(),
                                              screen_hash(frame)))

    def finish(self, harness: Harness) -> None:
        self._flush_wire(harness.ticks)
        frame = harness.last_frame if harness.last_frame is not None else harness.screen()
        self.rec.end = ScreenHash(harness.frames_shown, harness.ticks, harness.target.time(),
                                  screen_hash(frame))
        self.rec.ticks = harness.ticks
        write(self.path, self.rec)
        print(f"{harness.options.command}: recorded the session to {self.path} "
              f"({len(self.rec.events)} input events, {len(self.rec.hashes) + 1} screen "
              f"hashes)", file=sys.stderr)
