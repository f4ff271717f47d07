"""A ``--tablet`` read by a program outside the input layer (``rainbow run``), on a tablet
tape when the session is recorded, and from the recording's tape in a replay (where the
device is never opened).  See protocols/tablets/tape.py."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any


def recorded_tape() -> Any:
    """In a replay: the session's tablet tape (``T`` wire records), read from the recording
    a window at a time as the polls reach it; else None. A fault reading it again (the file
    changed, a poll over the budget) ends the tape and is the replay's fault."""
    from camlab88.emulator.harness import replay
    from camlab88.protocols.session import SessionFileError
    from camlab88.protocols.tablets.tape import Tape

    active = replay.active()
    if active is None:
        return None

    def fault(message: str) -> None:
        active.fault = active.fault or message

    def records() -> Iterator[bytes]:
        try:
            yield from active.rec.tape_records()
        except SessionFileError as exc:
            fault(str(exc))

    return Tape(where="the recording's tablet tape", records=records, on_fault=fault)


class TapedTablet:
    """``read(timeout)`` like a source; ``gone`` once it has been lost (not reopened)."""

    _state_exclude = ("source",)  # the device: kept as opened

    def __init__(self, source: Any, tape: Any, live: bool) -> None:
        self.source, self.tape, self.live = source, tape, live
        self.gone = False
        self.name = getattr(source, "name", "tablet")

    @classmethod
    def open(cls, text: str, record: bool) -> TapedTablet:
        from camlab88.protocols.tablets.sources import open_source
        from camlab88.protocols.tablets.tape import (
            RecordingSource,
            TapeRecorder,
            TapeSource,
            decoder_for,
        )

        tape = recorded_tape()
        if tape is not None:
            opened = tape.opens_now()
            return cls(None if opened is None else TapeSource(tape, opened, decoder_for), tape,
                       live=False)
        source = open_source(text)
        if not record:
            return cls(source, None, live=True)
        recorder = TapeRecorder()
        return cls(RecordingSource(source, recorder), recorder, live=True)

    def read(self, timeout: float = 0.0) -> list:
        from camlab88.protocols.tablets.sources import SourceLost

        try:
            if self.source is None:
                raise SourceLost(f"{self.name}: not on the recording's tablet tape")
            return self.source.read(timeout)
        finally:
            if self.tape is not None:
                self.tape.poll += 1

    def take_tape(self) -> bytes:
        from camlab88.protocols.tablets.tape import TapeRecorder

        return self.tape.take() if isinstance(self.tape, TapeRecorder) else b""

    def close(self) -> None:
        self.gone = True
        if self.source is not None:
            self.source.close()
            self.source = None
