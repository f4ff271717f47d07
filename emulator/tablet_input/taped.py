"""A ``--tablet`` read by a program outside the input layer (``rainbow run``, ``ca actors``),
on a tablet tape (a recording's ``T`` records; a save state's tablet input), and from the
recording's tape in a replay (where the device is never opened).  While a load runs a saved
session again the program reads a ``stand_in`` fed from the state's tape.  See
protocols/tablets/tape.py."""

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


class TapeKeeper:
    """What a tablet input does with its tablet tape (``tape``; ``_kept``: a replay's
    entries at the polls reached, None but in a replay kept for a state): a poll's end
    noted, the entries handed to a recording and to a save state."""

    tape: Any
    _kept: list[list] | None
    _tape_end = -1  # a stand-in's: the poll of its state tape's last entry

    def _count_polls_on_from(self, other: TapeKeeper | None) -> None:
        """After a load: this tape's polls count on from the stand-in ``other``'s (a
        recording's tape goes on from there); ValueError if the state's tape holds polls
        the session never reached."""
        polls = 0 if other is None or other.tape is None else other.tape.poll
        last = -1 if other is None else other._tape_end
        if last >= polls and last > 0:  # (poll 0's set-up is noted before the first poll)
            raise ValueError(f"state.tablet.tape: an entry at poll {last}; the session "
                             f"ran {polls} polls")
        if self.tape is not None:
            self.tape.poll = polls

    def _end_poll(self) -> None:
        if self.tape is not None:
            if self._kept is not None:  # a replay: the tape's entries of this poll
                self._kept += [[self.tape.poll, k, p] for k, p in self.tape.here()]
            self.tape.poll += 1

    def take_tape(self) -> bytes:
        """The tablet tape's entries since the last call (recording only)."""
        from camlab88.protocols.tablets.tape import TapeRecorder

        return self.tape.take("record") if isinstance(self.tape, TapeRecorder) else b""

    def take_state_tape(self) -> bytes:
        """The tablet tape's entries since the last call, for a save state: a live tablet's
        as noted, a replay's as its tape held them at the polls reached."""
        import json

        from camlab88.protocols.tablets.tape import TapeRecorder

        if isinstance(self.tape, TapeRecorder):
            return self.tape.take("state")
        new, self._kept = self._kept, [] if self._kept is not None else None
        return json.dumps(new, separators=(",", ":")).encode() if new else b""


class TapedTablet(TapeKeeper):
    """``read(timeout)`` like a source; ``gone`` once it has been lost (not reopened)."""

    _state_exclude = ("source",)  # the device: kept as opened

    def __init__(self, source: Any, tape: Any, live: bool, protocol: str = "") -> None:
        self.source, self.tape, self.live = source, tape, live
        self.protocol = protocol  # what a state's tablet input must match
        self.gone = False
        self.name = getattr(source, "name", "tablet")
        self._kept: list[list] | None = None  # a replay's, for a state (keep_for_state)

    @classmethod
    def open(cls, text: str, record: bool) -> TapedTablet:
        from camlab88.protocols.tablets.sources import open_source, parse_source
        from camlab88.protocols.tablets.tape import (
            RecordingSource,
            TapeRecorder,
            TapeSource,
            decoder_for,
        )

        spec = parse_source(text)
        protocol = spec.protocol or spec.kind  # (a HID tablet describes itself)
        tape = recorded_tape()
        if tape is not None:
            opened = tape.opens_now()
            return cls(None if opened is None else TapeSource(tape, opened, decoder_for), tape,
                       live=False, protocol=protocol)
        source = open_source(spec)
        # always on tape: a save state may keep it (keep_for_state), and --record records it
        recorder = TapeRecorder(("record",) if record else ())
        return cls(RecordingSource(source, recorder), recorder, live=True, protocol=protocol)

    def stand_in(self, entries: list | None) -> TapedTablet | None:
        """What the program reads while a load runs the session again: the state's tape
        ``entries`` decoded as a replay decodes a recording's; None (no tablet) where the
        saved session had none."""
        from camlab88.protocols.tablets.tape import Tape, TapeSource, decoder_for

        if entries is None:
            return None
        tape = Tape(entries, where="state.tablet.tape")
        opened = tape.opens_now()
        other = TapedTablet(None if opened is None else TapeSource(tape, opened, decoder_for),
                            tape, live=False, protocol=self.protocol)
        other._tape_end = entries[-1][0] if entries else -1
        return other

    def carry_on_from(self, other: TapedTablet | None) -> None:
        """After a load: the polls count on from the stand-in's (a recording's tape goes on
        from there), and a tablet the saved session had lost stays lost; ValueError if the
        state's tape holds polls the session never reached."""
        self._count_polls_on_from(other)
        if other is not None and other.gone and not self.gone:
            self.close()
        elif not self.live and self.source is None and self.tape is not None:
            from camlab88.protocols.tablets.tape import TapeSource, decoder_for

            opened = self.tape.opens_now()  # a recording begun from the state: its tablet
            if opened is not None:  # was opened at the start, first read here
                self.source = TapeSource(self.tape, opened, decoder_for)

    def read(self, timeout: float = 0.0) -> list:
        from camlab88.protocols.tablets.sources import SourceLost

        try:
            if self.source is None:
                raise SourceLost(f"{self.name}: not on the recording's tablet tape")
            return self.source.read(timeout)
        finally:
            self._end_poll()

    def keep_for_state(self) -> None:
        """A save state keeps what the tablet sends from now on (take_state_tape, which
        the state's log calls every tick: unread, the entries would pile up)."""
        from camlab88.protocols.tablets.tape import TapeRecorder

        if isinstance(self.tape, TapeRecorder):
            self.tape.add_reader("state")
        elif self.tape is not None:  # a replay: its tape's entries at the polls reached
            self._kept = []

    def close(self) -> None:
        self.gone = True
        if self.source is not None:
            self.source.close()
            self.source = None
