"""Recording and replay of a Rainbow session: the command stream, its replies, and the
input events injected into the device, in the order they happened.

File format (text, one entry a line)::

    # camlab88 rainbow recording v1
    > <hex of one command frame>
    < <hex of its reply frame>
    i <hex of one encoded input event>

Replay feeds the commands to a fresh device, injects the events at the same points, and
checks that every reply matches the recorded one.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from camlab88.base import budget
from camlab88.base.atomicfile import write_atomic
from camlab88.base.textinput import quote, read_text
from camlab88.protocols.rainbow.events import Event, decode_events, encode_event
from camlab88.protocols.rainbow.transport import Transport

MAGIC = "# camlab88 rainbow recording v1"
# What loading costs, measured (5 MB to 80 MB files of 2- to 4000-digit lines: 146-381 MB):
# the text and its split lines, twice its size; a line's string, bytes, tuple and number
# ~200 bytes (a million short lines: 190 MB)
TEXT_FACTOR = 2
LINE_BYTES = 200


class RecordingError(ValueError):
    pass


@dataclass
class Recording:
    entries: list[tuple[str, bytes]] = field(default_factory=list)
    source: str = "<recording>"  # the file it was loaded from, for replay's messages
    lines: list[int] = field(default_factory=list)  # each entry's line in that file

    def where(self, n: int) -> str:
        """``file:line`` of entry ``n`` (or ``<recording> entry n`` when not from a file)."""
        if n < len(self.lines):
            return f"{self.source}:{self.lines[n]}"
        return f"{self.source} entry {n}"

    def save(self, path: str | Path) -> None:
        path = Path(path)
        text = MAGIC + "\n" + "".join(f"{d} {b.hex()}\n" for d, b in self.entries)
        write_atomic(path, text)

    @classmethod
    def load(cls, path: str | Path) -> Recording:
        text = read_text(path, error=RecordingError, bom=False)
        count = text.count("\n") + 1  # refused before the lines are split (base.budget)
        budget.check(str(path), TEXT_FACTOR * len(text) + count * LINE_BYTES,
                     f"its {count:,} lines (a replay holds every entry)")
        lines = text.splitlines()
        del text
        if not lines or lines[0].strip() != MAGIC:
            raise RecordingError(f"{path}:1: not a camlab88 rainbow recording")
        rec = cls(source=str(path))
        for n, line in enumerate(lines[1:], 2):
            if not line.strip():
                continue
            d, _, h = line.partition(" ")
            if d not in (">", "<", "i"):
                raise RecordingError(f"{path}:{n}: unknown direction {quote(d, 20)}")
            try:
                data = bytes.fromhex(h)
            except ValueError:
                raise RecordingError(f"{path}:{n}: bad hex") from None
            if d == "i":
                decode_events(data, f"{path}:{n}")
            rec.entries.append((d, data))
            rec.lines.append(n)
        return rec


class RecordingTransport:
    """Wraps a transport and writes down every frame and reply that pass through it."""

    def __init__(self, inner: Transport, recording: Recording | None = None) -> None:
        self.inner = inner
        self.recording = recording or Recording()

    def call(self, frame: bytes) -> bytes:
        reply = self.inner.call(frame)
        self.recording.entries += [(">", frame), ("<", reply)]
        return reply

    def record_input(self, event: Event) -> None:
        """The wiring calls this as it injects an input event into the device."""
        self.recording.entries.append(("i", encode_event(event)))

    def close(self) -> None:
        self.inner.close()


@dataclass
class ReplayResult:
    commands: int = 0
    events: int = 0
    mismatches: list[str] = field(default_factory=list)


def replay(rec: Recording, call: Callable[[bytes], bytes],
           inject: Callable[[Event], None]) -> ReplayResult:
    result = ReplayResult()
    expect: bytes | None = None
    for n, (d, data) in enumerate(rec.entries):
        if d == ">":
            expect = call(data)
            result.commands += 1
        elif d == "<":
            if expect is None:
                result.mismatches.append(f"{rec.where(n)}: a reply with no command before it")
            elif expect != data:
                result.mismatches.append(f"{rec.where(n)}: the reply differs from the "
                                         f"recording (got {quote(expect.hex(), 40)}, recorded "
                                         f"{quote(data.hex(), 40)})")
            expect = None
        else:
            for e in decode_events(data, rec.where(n)):
                inject(e)
                result.events += 1
    return result
