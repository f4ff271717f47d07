"""A replay's window on its recording: the events, outside input and screen hashes of the
next few ticks, read from the file as the run reaches them (protocols.session
``SessionRecording.timeline``) and dropped once fed or compared, so a replay's memory does
not grow with the recording's length (docs/reliability.md, "Budget")."""

from __future__ import annotations

from collections import deque
from collections.abc import Iterator
from typing import Any

from camlab88.base import budget
from camlab88.protocols.session import ScreenHash, SessionFileError, SessionRecording

RECORD_BYTES = 300  # a held record, as protocols.session.parse counts one
_CHECK_EVERY = 1024  # records read between looks at what the window holds


class RecordWindow:
    """Records of ``rec`` read in order, each held from when it is read until its tick is
    played (an event at its tick, outside input the tick before it, a hash at its frame).
    ``fault`` is set (and nothing more is read) when the second reading fails: the file
    changed since the first pass, or one tick holds more than the memory budget."""

    def __init__(self, rec: SessionRecording, hashes: bool = True) -> None:
        self._want_hashes = hashes  # False: a replay without --check compares none
        self._items: Iterator[tuple[str, Any]] | None = rec.timeline()
        self._last = -1  # tick of the last record read
        self._read = 0
        self._limit = budget.limit()
        self.now = 0  # the harness's tick: what is older is dropped, not held
        self.events: deque[tuple[int, dict[str, Any]]] = deque()
        self.wire: deque[tuple[int, str, bytes]] = deque()  # at the tick it is fed before
        self.hashes: deque[ScreenHash] = deque()
        self.fault: str | None = None

    def events_at(self, tick: int) -> list[dict[str, Any]]:
        """The recorded events of ``tick`` (the harness ticks in order)."""
        self.now = tick
        self._fill(tick + 1)  # outside input of tick + 1 is fed before tick: read it too
        return [obj for _t, obj in _take(self.events, tick)]

    def wire_at(self, tick: int) -> list[tuple[str, bytes]]:
        """Outside input (``+`` bytes, ``-`` a hang-up) to feed before ``tick``."""
        self.now = tick
        self._fill(tick + 1)
        return [(d, data) for _t, d, data in _take(self.wire, tick)]

    def hash_at(self, frame: int) -> ScreenHash | None:
        """The recorded hash of ``frame``, None if the recording has none for it."""
        while (not self.hashes or self.hashes[-1].frame < frame) and self._pull():
            pass
        while self.hashes and self.hashes[0].frame < frame:
            self.hashes.popleft()
        return self.hashes[0] if self.hashes and self.hashes[0].frame == frame else None

    def close(self) -> None:
        close = getattr(self._items, "close", None)
        if close is not None:
            close()  # the file, when read from one
        self._items = None

    def _fill(self, tick: int) -> None:
        while self._last <= tick and self._pull():
            pass

    def _pull(self) -> bool:
        """Read one more record into the window; False at the end (or on a fault)."""
        if self._items is None:
            return False
        try:
            kind, value = next(self._items)
        except StopIteration:
            self._items = None
            return False
        except SessionFileError as exc:
            self.fault = str(exc)
            self.close()
            return False
        if kind == "event":
            self._last = value[0]
            if value[0] >= self.now:
                self.events.append((value[0], value[2]))
        elif kind == "wire":
            self._last = value[0]
            if value[0] - 1 >= self.now:  # recorded after its tick: fed before it
                self.wire.append((value[0] - 1, value[1], value[2]))
        else:
            self._last = value.tick
            if self._want_hashes:
                self.hashes.append(value)
        self._read += 1
        if self._read % _CHECK_EVERY == 0:
            self._check()
        return True

    def _check(self) -> None:
        count = len(self.events) + len(self.wire) + len(self.hashes)
        if count * RECORD_BYTES > self._limit:  # a crafted file: one tick of millions
            self.fault = (f"tick {self._last}: its {count:,} records and more, held for one "
                          f"tick, would need more than the memory budget of "
                          f"{budget.size_text(self._limit)} (raise it with camlab88 --budget "
                          f"SIZE or {budget.ENV}=SIZE)")
            self.close()


def _take(held: deque, tick: int) -> list:
    """The leading entries of ``held`` at ``tick`` (those before it dropped)."""
    while held and held[0][0] < tick:
        held.popleft()
    out = []
    while held and held[0][0] == tick:
        out.append(held.popleft())
    return out
