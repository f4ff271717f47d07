"""Session recordings: every chunk that crossed the line, both directions, timestamped.

File format (text, UTF-8; described fully in docs/link.md)::

    camlab88-link-recording 1
    line 9600 8N1
    xonxoff on
    # <t> <dir> <hex>: t = virtual time the chunk's last byte arrived (exact), dir > or <
    1/192 > 2b2d2a2f48
    0.040000 < 13
    end 2

``t`` is an exact decimal (at least 6 places) when one exists, else an exact fraction p/q.
A chunk's bytes went back to back, so byte i of n arrived at ``t - (n-1-i) * char_time``.
Flow-control bytes are recorded (they were on the wire). The ``end <chunks>`` trailer shows
the file is complete. Within a direction chunks are in time order; the two directions may
interleave in any order. The writer streams into a temporary file beside the target and renames
it into place on close, so a recording is either whole or absent.
"""

from __future__ import annotations

import contextlib
import os
import re
from collections.abc import Iterable
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import IO

from camlab88.base.atomicfile import commit, naming_user_path, output_target, temp_beside
from camlab88.base.textinput import quote, read_text
from camlab88.protocols.link.clock import TimeLike, to_time
from camlab88.protocols.link.line import XOFF, XON
from camlab88.protocols.link.settings import LineSettings

MAGIC = "camlab88-link-recording"
VERSION = 1
DIRECTIONS = (">", "<")
# Chunks may overlap the previous one in the same direction by this much (seconds) before the
# file is rejected: room for recordings written by hand or other tools with rounded times.
OVERLAP_TOLERANCE = Fraction(1, 10**6)

MAX_MERGED_CHUNK = 4096  # back-to-back pieces are merged into chunks up to about this size
_DECIMAL = re.compile(r"^[0-9]+(\.[0-9]+)?\Z")
_RATIO = re.compile(r"^[0-9]+/[1-9][0-9]*\Z")
_HEX = re.compile(r"^(?:[0-9a-fA-F]{2})+$")


class RecordingError(ValueError):
    """A recording file is malformed; the message names the file and line."""


def format_time(t: Fraction) -> str:
    """Exact text for a time: a decimal with >= 6 places if one exists, else p/q."""
    den = t.denominator
    twos = fives = 0
    while den % 2 == 0:
        den //= 2
        twos += 1
    while den % 5 == 0:
        den //= 5
        fives += 1
    if den != 1:
        return f"{t.numerator}/{t.denominator}"
    places = max(6, twos, fives)
    scaled = t * 10**places
    assert scaled.denominator == 1
    whole, frac = divmod(scaled.numerator, 10**places)
    return f"{whole}.{frac:0{places}d}"


# A recording's clock: ten years of line time is more than any session; a time beyond it is
# damage, and refusing it keeps float(t) and the frame count of a render finite.
MAX_SECONDS = 10**9
MAX_TIME_CHARS = 64


def parse_time(text: str) -> Fraction:
    if len(text) > MAX_TIME_CHARS:
        raise ValueError(f"time {text[:24]!r}... is {len(text)} characters long "
                         f"(at most {MAX_TIME_CHARS})")
    if _DECIMAL.match(text) or _RATIO.match(text):
        t = Fraction(text)
        if t > MAX_SECONDS:
            raise ValueError(f"time {text[:24]} s is past the {MAX_SECONDS} s a recording may span")
        return t
    raise ValueError(f"bad time {text[:24]!r} (want seconds as 0.123456 or p/q)")


@dataclass(frozen=True)
class RecordEntry:
    t: Fraction  # arrival time of the chunk's last byte
    direction: str  # ">" host to device, "<" device to host
    data: bytes  # as on the wire (flow-control bytes included)


class Recording:
    """A parsed recording: ``settings``, ``xonxoff``, and the chunks in file order.

    ``entries`` may be RecordEntry objects or ``(t, direction, bytes)`` tuples (float t is
    read as in clock.to_time)."""

    def __init__(
        self,
        settings: LineSettings,
        entries: Iterable[RecordEntry | tuple[TimeLike, str, bytes]],
        xonxoff: bool = True,
        path: str = "",
    ) -> None:
        self.settings = settings
        self.xonxoff = xonxoff
        self.path = path
        self.exact_entries: list[RecordEntry] = [
            e if isinstance(e, RecordEntry) else RecordEntry(to_time(e[0]), e[1], bytes(e[2]))
            for e in entries
        ]

    def __repr__(self) -> str:
        return f"<Recording {self.path or '(in memory)'}: {self.settings}, " \
            f"{len(self.exact_entries)} chunks>"

    @property
    def entries(self) -> list[tuple[float, str, bytes]]:
        """(t in float seconds, direction, bytes) per chunk, in file order."""
        return [(float(e.t), e.direction, e.data) for e in self.exact_entries]

    def stream(self, direction: str = ">", raw: bool = False) -> bytes:
        """Everything sent in one direction: what the far end received (flow-control bytes
        removed when XON/XOFF was on), or exactly what was on the wire with ``raw``."""
        data = b"".join(e.data for e in self.exact_entries if e.direction == direction)
        if raw or not self.xonxoff:
            return data
        return data.replace(bytes([XON]), b"").replace(bytes([XOFF]), b"")

    def arrivals(self, direction: str = ">") -> list[tuple[Fraction, bytes]]:
        """Delivered runs ``(arrival of the run's last byte, bytes)``, flow bytes removed."""
        ct = self.settings.char_time
        out: list[tuple[Fraction, bytes]] = []
        for e in self.exact_entries:
            if e.direction != direction:
                continue
            data = e.data
            if self.xonxoff and (XON in data or XOFF in data):
                # split around flow bytes, keeping each piece's own last-arrival time
                start = e.t - len(data) * ct  # when the chunk's first byte started
                piece = bytearray()
                for i, b in enumerate(data):
                    if b in (XON, XOFF):
                        if piece:
                            out.append((start + i * ct, bytes(piece)))
                            piece = bytearray()
                    else:
                        piece.append(b)
                if piece:
                    out.append((e.t, bytes(piece)))
            else:
                out.append((e.t, data))
        return out

    @property
    def duration(self) -> Fraction:
        return max((e.t for e in self.exact_entries), default=Fraction(0))


class Recorder:
    """Writes a recording; pass it to SerialLine(recorder=...) or call record() yourself."""

    def __init__(
        self, path: str | os.PathLike[str], settings: LineSettings, *, xonxoff: bool = True
    ) -> None:
        self.path = Path(path)
        self.settings = settings
        self.xonxoff = xonxoff
        self.count = 0
        self.closed = False
        self._ct = settings.char_time
        # Per direction, the last chunk, held back so back-to-back pieces become one chunk.
        self._held: dict[str, tuple[Fraction, bytes]] = {}
        self.path.parent.mkdir(parents=True, exist_ok=True)
        # the temporary name the stale-temp sweep knows (.NAME.PID.RANDOM.tmp); a directory
        # at the path is refused now, not when the line closes
        target, self._into = output_target(self.path)
        fd, self._tmp = (os.open(target, os.O_WRONLY), "") if self._into else \
            temp_beside(target)
        self._target = target
        self._fh: IO[str] = os.fdopen(fd, "w", encoding="utf-8", newline="\n")
        self._fh.write(
            f"{MAGIC} {VERSION}\nline {settings}\nxonxoff {'on' if xonxoff else 'off'}\n"
            "# <t> <dir> <hex>: t = arrival of the chunk's last byte (s); "
            "> host to device, < device to host\n"
        )

    def record(self, t: TimeLike, direction: str, data: bytes) -> None:
        if self.closed:
            raise ValueError(f"recorder for {self.path} is closed")
        if direction not in DIRECTIONS:
            raise ValueError(f"direction must be '>' or '<', not {direction!r}")
        if not data:
            return
        t = to_time(t)
        held = self._held.get(direction)
        if held is not None:
            if t - len(data) * self._ct == held[0] and len(held[1]) < MAX_MERGED_CHUNK:
                # back to back with the previous chunk: one chunk (the line commits in pieces)
                self._held[direction] = (t, held[1] + bytes(data))
                return
            self._write_held(direction)
        self._held[direction] = (t, bytes(data))

    def _write_held(self, direction: str) -> None:
        held = self._held.pop(direction, None)
        if held is not None:
            self._fh.write(f"{format_time(held[0])} {direction} {held[1].hex()}\n")
            self.count += 1

    def close(self) -> Path:
        """Finish the file and move it into place atomically."""
        if self.closed:
            return self.path
        for direction in DIRECTIONS:
            self._write_held(direction)
        self.closed = True
        try:
            with naming_user_path(self.path, self._tmp):
                self._fh.write(f"end {self.count}\n")
                self._fh.flush()
                if not self._into:
                    os.fsync(self._fh.fileno())
                self._fh.close()
            if not self._into:
                commit(self._tmp, self._target)
        except OSError:
            self._discard()
            raise
        return self.path

    def _discard(self) -> None:
        with contextlib.suppress(OSError):
            self._fh.close()
        if self._tmp:
            with contextlib.suppress(OSError):
                os.unlink(self._tmp)

    def abort(self) -> None:
        """Discard the recording (nothing is written at ``path``)."""
        if not self.closed:
            self.closed = True
            self._discard()

    def __enter__(self) -> Recorder:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def parse_recording(text: str, name: str = "<recording>") -> Recording:
    """Parse recording text; errors name ``name`` and the line number."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()

    def fail(lineno: int, why: str) -> RecordingError:
        return RecordingError(f"{name}:{lineno}: {why}")

    if not lines or lines[0].split() != [MAGIC, str(VERSION)]:
        first = lines[0].split()[:2] if lines else []
        if len(first) == 2 and first[0] == MAGIC:
            raise fail(1, f"unsupported recording version {quote(first[1])} (this reads {VERSION})")
        raise fail(1, f"not a camlab88 link recording (expected '{MAGIC} {VERSION}')")
    settings: LineSettings | None = None
    xonxoff: bool | None = None
    entries: list[RecordEntry] = []
    last_end: dict[str, Fraction] = {}
    ended = False
    for lineno, raw in enumerate(lines[1:], start=2):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        if ended:
            raise fail(lineno, "text after the 'end' line")
        fields = line.split()
        key = fields[0]
        if key == "line":
            if settings is not None or entries:
                raise fail(lineno, "'line' must appear once, before the data")
            try:
                settings = LineSettings.parse(" ".join(fields[1:]))
            except ValueError as exc:
                raise fail(lineno, str(exc)) from None
            continue
        if key == "xonxoff":
            if len(fields) != 2 or fields[1] not in ("on", "off"):
                raise fail(lineno, "expected 'xonxoff on' or 'xonxoff off'")
            xonxoff = fields[1] == "on"
            continue
        if key == "end":
            if len(fields) != 2 or not (fields[1].isascii() and fields[1].isdigit()):
                raise fail(lineno, "expected 'end <number of chunks>'")
            if int(fields[1]) != len(entries):
                raise fail(
                    lineno, f"'end' says {fields[1]} chunks but the file has {len(entries)}"
                )
            ended = True
            continue
        if settings is None:
            raise fail(lineno, "data before the 'line <baud> <framing>' header")
        if len(fields) != 3:
            raise fail(lineno, f"expected '<time> <direction> <hex bytes>', got {line[:60]!r}")
        t_text, direction, hex_text = fields
        try:
            t = parse_time(t_text)
        except ValueError as exc:
            raise fail(lineno, str(exc)) from None
        if direction not in DIRECTIONS:
            raise fail(lineno, f"direction must be '>' or '<', not {quote(direction)}")
        if not _HEX.match(hex_text):
            raise fail(lineno, f"bad hex bytes {hex_text[:40]!r} (need an even number of 0-9a-f)")
        data = bytes.fromhex(hex_text)
        ct = settings.char_time
        first_start = t - len(data) * ct
        if first_start < 0:
            raise fail(lineno, f"{len(data)} bytes cannot have arrived by {t_text} s")
        previous = last_end.get(direction)
        if previous is not None and first_start < previous - OVERLAP_TOLERANCE:
            raise fail(
                lineno,
                f"chunk overlaps the previous '{direction}' chunk (starts at "
                f"{float(first_start):.6f} s, the previous one ended at {float(previous):.6f} s)",
            )
        last_end[direction] = t
        entries.append(RecordEntry(t, direction, data))
    if settings is None:
        raise fail(len(lines) + 1, "no 'line <baud> <framing>' header")
    if not ended:
        raise fail(len(lines) + 1, "truncated recording: no 'end' line")
    return Recording(settings, entries, True if xonxoff is None else xonxoff, name)


def read_recording(path: str | os.PathLike[str]) -> Recording:
    """Read a recording file; a bad file raises RecordingError naming the file and line."""
    text = read_text(path, error=RecordingError, bom=False)
    return parse_recording(text, str(path))
