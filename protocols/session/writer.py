"""A session recording written as it is made (``--record``): the records go to a temporary
file beside the target as the run makes them and the file is renamed into place at the end,
so the recorder's memory does not grow with the session's length and an interrupted run
leaves no half file under the target's name (an older recording there stays as it was).

The bytes are those ``format.dumps`` writes for the same session: the body records of a tick
are held until a later tick begins, then written in the order ``dumps`` sorts them (events,
wire, the screen hash; in the order they came within each).
"""

from __future__ import annotations

import os
from fractions import Fraction
from pathlib import Path
from typing import IO, Any

from camlab88.protocols.session.format import (
    EVENT,
    HASH,
    WIRE,
    ScreenHash,
    end_record,
    event_record,
    hash_record,
    head_records,
    line,
    wire_record,
)


class SessionWriter:
    """``event``/``wire``/``hash`` as the run makes them (ticks never going back), then
    ``finish(end, ticks)`` (the file renamed into place) or ``abandon()`` (the temporary
    file removed). OSError names ``path``."""

    def __init__(self, path: str | os.PathLike[str], argv: list[str], hash_every: int,
                 headless: bool, files: dict[str, bytes]) -> None:
        from camlab88.base.atomicfile import naming_user_path, open_into, output_target, temp_beside

        self.path = path
        self._target, into = output_target(path)
        self._tmp: str | None = None
        if into:  # a device or a FIFO: written into as it comes, never replaced
            self._fh: IO[bytes] = open_into(self._target, path)
        else:
            fd, self._tmp = temp_beside(self._target)
            self._fh = os.fdopen(fd, "wb")
        self._naming = lambda: naming_user_path(path, self._tmp)
        self._tick = -1  # the latest tick held
        self._held: list[tuple[int, int, dict[str, Any]]] = []
        self.events = self.hashes = 0
        self._write(b"".join(line(r) for r in head_records(argv, hash_every, headless, files)))

    def event(self, tick: int, time: Fraction, event: dict[str, Any]) -> None:
        self.events += 1
        self._add(tick, EVENT, event_record(tick, time, event))

    def wire(self, tick: int, direction: str, data: bytes) -> None:
        self._add(tick, WIRE, wire_record(tick, direction, data))

    def hash(self, h: ScreenHash) -> None:
        self.hashes += 1
        self._add(h.tick, HASH, hash_record(h))

    def finish(self, end: ScreenHash, ticks: int) -> None:
        """The end record written, the file synced and renamed into place."""
        from camlab88.base.atomicfile import commit

        self._release()
        self._write(line(end_record(end, ticks)))
        with self._naming():
            self._fh.flush()
            if self._tmp is not None:
                os.fsync(self._fh.fileno())
            self._fh.close()
        if self._tmp is not None:
            commit(self._tmp, self._target)
            self._tmp = None

    def abandon(self) -> None:
        """Stop without a recording: the temporary file removed, the target untouched."""
        try:
            self._fh.close()
        except OSError:
            pass  # a full disk refusing the last buffered bytes: the file goes anyway
        if self._tmp is not None:
            Path(self._tmp).unlink(missing_ok=True)
            self._tmp = None

    def _add(self, tick: int, order: int, record: dict[str, Any]) -> None:
        if tick > self._tick:  # a later tick: the ones held are complete
            self._release()
            self._tick = tick
        self._held.append((tick, order, record))

    def _release(self) -> None:
        held = sorted(self._held, key=lambda x: (x[0], x[1]))  # stable: as they came
        self._held = []
        self._write(b"".join(line(r) for _t, _o, r in held))

    def _write(self, data: bytes) -> None:
        with self._naming():
            self._fh.write(data)
