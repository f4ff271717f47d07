"""Reading a session recording (format: protocols.session.format), checking every record.

Every refusal names the file, line and column: bad UTF-8 or JSON, an unknown record type, a
missing or mistyped key, another format, a newer version, ticks going back, a time that does
not go with its tick (back in time, or two times for one tick), a screen hash at a frame no
run can reach (not the next multiple of ``hash_every``; a run begun from ``--load-state``
hashes its first frame, the state's, first; more frames than ticks, past the end), an end
whose frames the hashes do not cover (so the frames a replay runs are bounded by the file's
size), a file whose content does not match its hash, more inflated data than
``MAX_TOTAL``, or no ``end`` record (a truncated recording).
"""

from __future__ import annotations

import base64
import binascii
import hashlib
import json
import re
import zlib
from collections.abc import Iterable, Iterator
from fractions import Fraction
from typing import Any

import numpy as np

from camlab88.base import budget
from camlab88.protocols.session.format import (
    _KEYS,
    FORMAT,
    VERSION,
    ScreenHash,
    SessionFileError,
    SessionRecording,
)

MAX_DATA = 256 * 1024 * 1024  # one record's data, inflated: more is a damaged or hostile file
MAX_TOTAL = 1024 * 1024 * 1024  # all records' data together, inflated
MAX_COUNT = 10**12  # ticks, frames, hash_every: 10^12 ticks is centuries of virtual time
# what str(Fraction) writes (and a decimal by hand); no exponent, so '1e99999999999' cannot
# make Fraction compute 10**99999999999
_TIME = re.compile(r"[0-9]{1,40}(?:/[0-9]{1,40}|\.[0-9]{1,40})?")


class _Reader:
    def __init__(self, name: str) -> None:
        self.name = name
        self.line = 0
        self.rec: SessionRecording | None = None
        self.last_tick = 0
        self.last_time: tuple[int, Fraction] | None = None  # (tick, time) of the last
        self.last_frame = 0
        self.hashed = False
        self.resumed = False
        self.total = 0
        self.ended = False
        self.traffic = True  # keep the > and < wire records (a replay does not need them)
        # a replay's first pass: events, outside input (+, -) and hashes are checked, not
        # kept; the replay reads them again a window at a time (emulator.harness.replay_window)
        self.window = False
        self.timeline: list[tuple[str, Any]] = []  # the replay pass: what the line held
        self.hold = True  # keep the files (the replay pass has them)

    def fail(self, message: str, col: int = 1) -> SessionFileError:
        return SessionFileError(self.name, self.line, col, message)

    def record(self, text: str) -> dict[str, Any]:
        try:
            obj = json.loads(text)
        except json.JSONDecodeError as exc:
            raise SessionFileError(self.name, self.line, exc.colno,
                                   f"not JSON: {exc.msg}") from None
        except RecursionError:
            raise self.fail("not JSON: nested too deeply") from None
        except ValueError as exc:  # an integer past Python's 4300-digit conversion limit
            raise self.fail(f"not JSON: {str(exc).split(':')[0]}") from None
        if not isinstance(obj, dict) or not isinstance(obj.get("type"), str):
            raise self.fail('expected a JSON object with a "type"')
        self.newer(obj)  # before the key checks: a newer version may have other keys
        keys = _KEYS.get(obj["type"])
        if keys is None:
            raise self.fail(f"unknown record type {obj['type']!r}; expected one of "
                            f"{', '.join(_KEYS)}")
        for key, kind in keys.items():
            if key not in obj or not isinstance(obj[key], kind) or \
                    (kind is int and isinstance(obj[key], bool)):
                raise self.fail(f"{obj['type']} record: {key!r} missing or not "
                                f"{getattr(kind, '__name__', kind)}")
            if kind is int and key != "version" and not 0 <= obj[key] <= MAX_COUNT:
                raise self.fail(f"{obj['type']} record: {key} {obj[key]} outside "
                                f"0..{MAX_COUNT}")
        return obj

    def newer(self, obj: dict[str, Any]) -> None:
        v = obj.get("version")
        if obj["type"] == "header" and obj.get("format") == FORMAT and isinstance(v, int) \
                and v > VERSION:
            raise self.fail(f"written by a newer camlab88 (format version {v}); this one "
                            f"reads version {VERSION}: upgrade camlab88")

    def header(self, obj: dict[str, Any]) -> None:
        if obj["type"] != "header" or obj["format"] != FORMAT:
            raise self.fail(f"not a camlab88 session recording (expected a {FORMAT} header)")
        if obj["version"] != VERSION:
            raise self.fail(f"unknown format version {obj['version']} (expected {VERSION})")
        if not all(isinstance(a, str) for a in obj["argv"]) or not obj["argv"]:
            raise self.fail("header: argv must be a non-empty list of strings")
        if obj["hash_every"] < 1:
            raise self.fail("header: hash_every must be at least 1")
        self.rec = SessionRecording(list(obj["argv"]), obj["hash_every"], obj["headless"])
        # a run begun from --load-state starts at the state's frame: its first hash is that
        # frame's (any), the rest every multiple after it as in any recording
        self.resumed = any(a == "--load-state" or a.startswith("--load-state=")
                           for a in obj["argv"])

    def tick(self, obj: dict[str, Any], key: str = "tick") -> int:
        t = obj[key]
        if t < self.last_tick:
            raise self.fail(f"{key} {t} goes back (after {self.last_tick})")
        self.last_tick = t
        return t

    def time(self, text: str) -> Fraction:
        try:
            if not _TIME.fullmatch(text):
                raise ValueError
            return Fraction(text)
        except (ValueError, ZeroDivisionError):
            raise self.fail(f"time {text[:60]!r} is not a number of seconds (N, N/M or "
                            f"N.M, at most 40 digits each)") from None

    def data(self, text: str) -> bytes:
        try:
            packed = base64.b64decode(text.encode("ascii"), validate=True)
        except (binascii.Error, UnicodeEncodeError):
            raise self.fail("data is not base64") from None
        inflate = zlib.decompressobj()
        try:
            data = inflate.decompress(packed, MAX_DATA + 1)
        except zlib.error:
            raise self.fail("data is not zlib-compressed") from None
        if len(data) > MAX_DATA or not inflate.eof:
            raise self.fail(f"data is damaged or larger than {MAX_DATA} bytes")
        self.total += len(data)
        if self.total > MAX_TOTAL:
            raise self.fail(f"the records' data comes to more than {MAX_TOTAL} bytes")
        return data

    def body(self, obj: dict[str, Any]) -> None:
        assert self.rec is not None
        kind = obj["type"]
        if self.ended:
            raise self.fail("a record after the end record")
        if kind == "header":
            raise self.fail("a second header")
        getattr(self, f"_{kind}")(obj)

    def _file(self, obj: dict[str, Any]) -> None:
        data = self.data(obj["data"])
        if hashlib.sha256(data).hexdigest() != obj["sha256"]:
            raise self.fail(f"file {obj['name']!r}: content does not match its sha256")
        if self.hold:
            self.rec.files[obj["name"]] = data

    def _event(self, obj: dict[str, Any]) -> None:
        tick = self.tick(obj)
        item = (tick, self.timed(tick, obj["time"]), obj["event"])
        if self.window:
            self.timeline.append(("event", item))
            return
        self.rec.events.append(item)

    def timed(self, tick: int, text: str) -> Fraction:
        """The time at ``tick``: never back, and one time for one tick."""
        t = self.time(text)
        if self.last_time is not None:
            last_tick, last = self.last_time
            if t < last or (tick == last_tick and t != last):
                raise self.fail(f"time {text} at tick {tick} does not go with time {last} at "
                                f"tick {last_tick}")
        self.last_time = (tick, t)
        return t

    def _wire(self, obj: dict[str, Any]) -> None:
        if obj["dir"] not in (">", "<", "+", "-", "T"):
            raise self.fail(f"wire direction {obj['dir']!r}; expected >, <, +, - or T")
        data = self.data(obj["data"])
        if obj["dir"] == "T":  # a tablet tape's entries: checked like every other record
            from camlab88.protocols.tablets.tape import TapeError, parse_chunk

            try:
                parse_chunk(data, "tablet tape")
            except TapeError as exc:
                raise self.fail(str(exc)) from None
        tick = self.tick(obj)
        if self.window and obj["dir"] in "+-":
            self.timeline.append(("wire", (tick, obj["dir"], data)))
        elif self.window and obj["dir"] == "T":  # the tape: a pass of its own reads it again
            self.timeline.append(("tape", data))
        elif self.traffic:
            self.rec.wire.append((tick, obj["dir"], data))

    def _hash(self, obj: dict[str, Any]) -> None:
        frame, every = obj["frame"], self.rec.hash_every
        first_of_resumed = self.resumed and not self.hashed
        if frame != self._next(every) and not first_of_resumed:  # every multiple is hashed
            raise self.fail(f"hash record: frame {frame} is not the next multiple of "
                            f"hash_every {every} after frame {self.last_frame}")
        screen = self._screen(obj, frame)
        if self.window:
            self.timeline.append(("hash", screen))
        else:
            self.rec.hashes.append(screen)
        self.last_frame, self.hashed = frame, True

    def _next(self, every: int) -> int:
        """The next multiple of ``every`` after the last hashed frame."""
        return (self.last_frame // every + 1) * every

    def _end(self, obj: dict[str, Any]) -> None:
        every = self.rec.hash_every
        if not self.last_frame <= obj["frames"] < self._next(every):
            raise self.fail(f"end record: {obj['frames']} frames, but the screen hashes "
                            f"(every {every} frames) stop at frame {self.last_frame}")
        self.rec.end = self._screen(obj, obj["frames"])
        self.rec.ticks = obj["ticks"]
        self.ended = True

    def _screen(self, obj: dict[str, Any], frame: int) -> ScreenHash:
        sha = obj["sha256"]
        if len(sha) != 64 or any(c not in "0123456789abcdef" for c in sha):
            raise self.fail("sha256 must be 64 lowercase hex digits")
        tick = self.tick(obj, "tick" if "tick" in obj else "ticks")
        if frame > tick:  # a run shows at most one frame a tick
            raise self.fail(f"{obj['type']} record: frame {frame} after only {tick} ticks")
        return ScreenHash(frame, tick, self.timed(tick, obj["time"]), sha)


# What a recording costs in memory, besides its bytes (held once, split into lines once):
# a record ~300 bytes (its line's object, its parsed tuple, its entry in the replay's tables);
# the longest line ~6 times its length while it is decoded (text, JSON, base64, inflated)
RECORD_BYTES = 300
LINE_FACTOR = 6
_BLOCK = 1 << 24


def shape(raw: bytes | memoryview) -> tuple[int, int]:
    """(lines, longest line's length) of ``raw``, read in blocks (no copy of it)."""
    view = memoryview(raw)
    return shape_of_blocks(view[at:at + _BLOCK] for at in range(0, len(view), _BLOCK))


def shape_of_file(fh: Any) -> tuple[int, int]:
    """(lines, longest line's length) of an open file from where it is, 16 MB at a time."""
    return shape_of_blocks(iter(lambda: fh.read(_BLOCK), b""))


def shape_of_blocks(blocks: Iterable[bytes | memoryview]) -> tuple[int, int]:
    lines, longest, run = 0, 0, 0
    for chunk in blocks:
        block = np.frombuffer(chunk, np.uint8)
        ends = np.flatnonzero(block == 10)
        if not ends.size:
            run += block.size
            continue
        gaps = np.diff(ends) - 1
        longest = max(longest, run + int(ends[0]), int(gaps.max()) if gaps.size else 0)
        run = block.size - int(ends[-1]) - 1
        lines += ends.size
    return lines + (run > 0), max(longest, run)


def check_cost(name: str, size: int, lines: int, longest: int) -> None:
    """Refuse a recording over the memory budget (base.budget) before it is parsed."""
    need = 2 * size + lines * RECORD_BYTES + longest * LINE_FACTOR
    what = (f"its {lines:,} records" if lines * RECORD_BYTES >= longest * LINE_FACTOR else
            f"its {longest:,}-byte line")
    budget.check(name, need, what)


def parse_lines(raw: bytes, name: str) -> SessionRecording:
    """The recording in ``raw`` (the bytes of file ``name``)."""
    check_cost(name, len(raw), *shape(raw))
    return parse_stream(raw.split(b"\n"), name)


def stream_lines(fh: Any, name: str) -> Iterator[bytes]:
    """The lines of an open recording, one at a time (no line kept after the next is read),
    after a first pass in blocks has refused a line longer than the budget can decode
    (before any line is read whole)."""
    _lines, longest = shape_of_file(fh)
    budget.check(name, longest * LINE_FACTOR, f"its {longest:,}-byte line")
    fh.seek(0)
    for line in fh:
        yield line[:-1] if line.endswith(b"\n") else line


def parse_stream(lines: Iterable[bytes], name: str, traffic: bool = True) -> SessionRecording:
    """The recording in ``lines``, checked record by record. ``traffic=False`` (a replay's
    first pass): only the header, the input files and the end are kept — the program/device
    traffic (``>``, ``<``), the events, the outside input (``+``, ``-``), the tablet tape
    (``T``) and the screen hashes are checked and dropped, so memory does not grow with the
    recording's length (the replay reads them again a window at a time: ``timeline``)."""
    reader = _Reader(name)
    reader.traffic, reader.window = traffic, not traffic
    for _ in _checked(reader, lines):
        reader.timeline.clear()
    return _whole(reader, name)


def timeline(lines: Iterable[bytes], name: str, tape: bool = False) -> Iterator[Any]:
    """A replay's second pass over a recording its first pass accepted: every event
    ``("event", (tick, time, event))``, outside input ``("wire", (tick, dir, data))`` and
    screen hash ``("hash", ScreenHash)`` in file order, checked again as they come (nothing
    else kept); a fault raises SessionFileError as the first pass would have. ``tape``: the
    tablet tape's records' data alone (a pass the replay's tablet reads as its polls go)."""
    reader = _Reader(name)
    reader.traffic, reader.window, reader.hold = False, True, False
    for _ in _checked(reader, lines):
        for kind, value in reader.timeline:
            if (kind == "tape") == tape:
                yield value if tape else (kind, value)
        reader.timeline.clear()
    _whole(reader, name)


def _checked(reader: _Reader, lines: Iterable[bytes]) -> Iterator[None]:
    """Each record of ``lines`` read and checked by ``reader``, one at a time."""
    for reader.line, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            text = line.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise reader.fail("not UTF-8", exc.start + 1) from None
        obj = reader.record(text)
        if reader.rec is None:
            reader.header(obj)
        else:
            reader.body(obj)
        yield


def _whole(reader: _Reader, name: str) -> SessionRecording:
    """The recording ``reader`` read, refused if it was empty or had no end."""
    if reader.rec is None:
        raise SessionFileError(name, 1, 1, "empty: not a camlab88 session recording")
    if not reader.ended:
        raise SessionFileError(name, reader.line, 1, "truncated: the recording has no end "
                               "record (was the program stopped while recording?)")
    return reader.rec
