"""A tablet's session on tape: what the device sent, at which poll, and the decoder's setup.

Recording (``TapeRecorder`` + ``RecordingSource`` around the real source) notes, per poll of
the input layer: ``open`` (the decoder's setup: the HID report descriptor or vendor profile,
or the serial protocol, its options, the model and the start-up replies), ``raw`` (serial
bytes as read, or one HID report), ``flush`` (a serial silence ended a partial reply),
``lost`` (the device went away, with the message), ``idle`` (a serial stream's silence level
changed: 0 streaming, 1 past the stroke-ending silence, 2 past the mouse-fallback silence),
and once ``calibration``.  Replaying (``TapeSource``) runs the *same decoder* on the recorded
bytes at the same polls, so a program fed from the tape takes every decision it took live:
nothing on the tape depends on the wall clock any more.

Entries are JSON: ``[poll, kind, payload]``; bytes are hex.  A tape is data: it names no
device to open.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterator
from dataclasses import asdict
from typing import Any

from camlab88.protocols.tablets.events import DeviceReply, TabletEvent, TabletModel
from camlab88.protocols.tablets.sources import SourceLost, TabletSource


class TapeError(ValueError):
    """A tablet tape that cannot be replayed (the message says which entry and why)."""


KINDS = ("open", "raw", "flush", "lost", "idle", "calibration")
MAX_DEPTH = 8  # an entry is [poll, kind, payload]; an opening's model nests two more levels
MAX_POLL = 10**12  # as a session recording's ticks
MAX_RAW = 1 << 20  # hex digits of one read: a serial read or one HID report is far less
MAX_TEXT = 4096  # a lost device's message, a name


def _payload_fault(kind: str, payload: Any) -> str | None:
    """Why ``payload`` cannot be a ``kind`` entry's (None: it can)."""
    if kind == "raw":
        if not isinstance(payload, str) or len(payload) > MAX_RAW:
            return f"a raw entry's payload is hex text of at most {MAX_RAW} digits"
        try:
            bytes.fromhex(payload)
        except ValueError:
            return "a raw entry's payload is not hex"
        return None
    if kind == "flush":
        return None if payload is None else "a flush entry has no payload (null)"
    if kind == "lost":
        return None if isinstance(payload, str) and len(payload) <= MAX_TEXT else \
            "a lost entry's payload is the message (text)"
    if kind == "idle":
        return None if type(payload) is int and 0 <= payload <= 2 else \
            "an idle entry's payload is a silence level 0, 1 or 2"
    if kind == "open":
        return _open_fault(payload)
    return None if payload is None or isinstance(payload, dict) else \
        "a calibration entry's payload is an object or null (none)"


def _open_fault(opened: Any) -> str | None:
    """Why ``opened`` is not a recorded opening (describe_open's shape)."""
    if not isinstance(opened, dict) or not isinstance(opened.get("name", ""), str):
        return "an open entry's payload is an object with a name"
    if opened.get("kind") == "hid":
        ids = (opened.get("vid"), opened.get("pid"))
        descriptor = opened.get("descriptor")
        if not all(type(v) is int and 0 <= v <= 0xFFFF for v in ids) or not (
                descriptor is None or isinstance(descriptor, str)):
            return "a HID opening has vid and pid 0..65535 and a hex descriptor or null"
        return None
    if opened.get("kind") == "serial":
        options, model, replies = (opened.get(k) for k in ("options", "model", "replies"))
        if not (isinstance(opened.get("protocol"), str) and isinstance(model, dict)
                and isinstance(options, dict | None) and isinstance(replies, list | None)
                and all(isinstance(r, str) for r in replies or [])
                and isinstance(opened.get("parmrk", False), bool)):
            return ("a serial opening has a protocol (text), options (an object), a model "
                    "(an object), replies (texts) and parmrk (true or false)")
        return None
    return f"an open entry's kind is 'hid' or 'serial', not {str(opened.get('kind'))[:20]!r}"


def check_entries(entries: Any, where: str) -> list[list[Any]]:
    """``entries`` if every one is ``[poll, kind, payload]`` of a known kind with a payload
    of its type; TapeError naming the entry otherwise."""
    if not isinstance(entries, list):
        raise TapeError(f"{where}: a record is not a list of entries")
    for n, entry in enumerate(entries):
        if not (isinstance(entry, list) and len(entry) == 3 and type(entry[0]) is int
                and 0 <= entry[0] <= MAX_POLL and isinstance(entry[1], str)):
            raise TapeError(f"{where}: entry {n + 1} is not [poll, kind, payload] (a poll "
                            f"0..{MAX_POLL})")
        if entry[1] not in KINDS:
            raise TapeError(f"{where}: entry {n + 1}: unknown kind {entry[1][:20]!r}; one of "
                            f"{', '.join(KINDS)}")
        fault = _payload_fault(entry[1], entry[2])
        if fault is not None:
            raise TapeError(f"{where}: entry {n + 1}: {fault}")
    return entries


def parse_chunk(chunk: bytes, where: str = "tablet tape") -> list[list[Any]]:
    """One ``T`` record's entries, checked (JSON nested at most MAX_DEPTH deep)."""
    from camlab88.base.textinput import loads_json

    try:
        text = chunk.decode("utf-8")
    except UnicodeDecodeError:
        raise TapeError(f"{where}: not UTF-8 text") from None
    return check_entries(loads_json(text, where, TapeError, max_depth=MAX_DEPTH), where)


class TapeRecorder:
    """Collects entries; ``take(reader)`` hands out the new ones as bytes. Each of
    ``readers`` (a session record's ``record``, a save state's ``state``) takes its own."""

    def __init__(self, readers: tuple[str, ...] = ("record",)) -> None:
        self.poll = 0
        self._unread: dict[str, list[list[Any]]] = {r: [] for r in readers}

    def note(self, kind: str, payload: Any) -> None:
        entry = [self.poll, kind, payload]
        for unread in self._unread.values():
            unread.append(entry)

    def add_reader(self, reader: str) -> None:
        """From now on ``reader`` takes the entries noted too."""
        self._unread.setdefault(reader, [])

    def take(self, reader: str = "record") -> bytes:
        """The entries since ``reader``'s last take (then dropped: memory stays bounded)."""
        new = self._unread.get(reader)
        if not new:
            return b""
        self._unread[reader] = []
        return json.dumps(new, separators=(",", ":")).encode()


def _idle_level(source: Any, idle: float) -> int:
    if idle >= source.stall_fallback:
        return 2
    return 1 if idle >= source.stall_release else 0


def describe_open(source: Any) -> dict[str, Any]:
    """What a replay needs to build the same decoder as ``source`` (HID or serial)."""
    if hasattr(source, "pump"):  # HidSource
        vid, pid = source.vid_pid
        return {"kind": "hid", "name": source.name, "vid": vid, "pid": pid,
                "descriptor": source.descriptor.hex() if source.descriptor else None}
    spec = source.spec
    return {"kind": "serial", "name": source.name, "protocol": spec.protocol,
            "options": dict(spec.options), "model": asdict(source.model),
            "replies": [r.text for r in source.replies],
            "parmrk": getattr(source.parser, "_parmrk", None) is not None}


def decoder_for(opened: dict[str, Any]) -> Any:
    """The decoder a recorded opening used (``feed(bytes)``, ``flush()``, ``model``)."""
    try:
        if opened.get("kind") == "hid":
            from camlab88.protocols.tablets.hid_source import HidReportDecoder

            descriptor = opened.get("descriptor")
            return HidReportDecoder(int(opened["vid"]), int(opened["pid"]),
                                    bytes.fromhex(descriptor) if descriptor else None,
                                    str(opened.get("name", "tablet tape")))
        if opened.get("kind") == "serial":
            return SerialTapeDecoder(opened)
    except (KeyError, TypeError, ValueError, AttributeError) as exc:
        raise TapeError(f"tablet tape: cannot rebuild the decoder: {exc}") from None
    raise TapeError(f"tablet tape: unknown source kind {opened.get('kind')!r}")


class RecordingSource(TabletSource):
    """The real source, noting on the tape everything its reads bring."""

    def __init__(self, inner: TabletSource, tape: TapeRecorder) -> None:
        self.inner, self.tape = inner, tape
        self.name = inner.name
        self._opened = False
        self._level = 0
        self._now = 0.0
        inner.on_raw = lambda data: tape.note("raw", bytes(data).hex())
        if hasattr(inner, "on_flush"):
            inner.on_flush = lambda: tape.note("flush", None)
        if hasattr(inner, "clock"):  # a streaming serial tablet: silence is watched
            self.clock = lambda: self._now
            self.stall_release = inner.stall_release
            self.stall_fallback = inner.stall_fallback

    # the inner source's, read live (a Wacom's model changes once it has said what it is)
    model = property(lambda self: self.inner.model)
    last_data = property(lambda self: self.inner.last_data)

    def read(self, timeout: float = 0.0) -> list[TabletEvent]:
        if not self._opened:  # noted at the poll that first reads it (when it was adopted)
            self._opened = True
            self.tape.note("open", describe_open(self.inner))
        try:
            events = self.inner.read(timeout)
        except SourceLost as exc:
            self.tape.note("lost", str(exc))
            raise
        if hasattr(self, "clock"):
            self._now = self.inner.clock()
            level = _idle_level(self, self._now - self.last_data)
            if level != self._level:
                self._level = level
                self.tape.note("idle", level)
        return events

    def close(self) -> None:
        self.inner.close()


ENTRY_BYTES = 200  # a held entry (its list, tuple and payload), as the budget counts one


class Tape:
    """A recorded tape and the replay's poll counter. It holds a window of the tape: the
    entries from the poll it is at to the first entry past it, read from ``records`` (a
    fresh reading of the tape's ``T`` records, in order, each call) as the polls reach them
    and dropped once passed, so its memory does not grow with the tape's length.
    ``on_fault`` hears why it stopped reading (one poll holding more than the memory budget);
    a tape given as ``entries`` is read from them."""

    # rebuilt, not saved: a loaded state's reading goes on from ``_read`` entries in
    _state_exclude = ("_records", "_reading", "_pos", "on_fault")

    def __init__(self, entries: list[list[Any]] | None = None, where: str = "tablet tape",
                 records: Callable[[], Iterator[bytes]] | None = None,
                 on_fault: Callable[[str], None] | None = None) -> None:
        self.where = where
        if records is None:
            held = [json.dumps(check_entries(entries or [], where)).encode()]
            records = held.__iter__  # a fresh reading each call
        self._records = records
        self._reading: Iterator[list[Any]] | None = None
        self._pos = 0  # entries the reading has given
        self.on_fault = on_fault
        self.by_poll: dict[int, list[tuple[str, Any]]] = {}
        self._read = 0  # entries read so far (a loaded state's fresh reading skips them)
        self._ahead = -1  # the poll of the last entry read
        self._held = 0
        self._ended = False
        self.poll = 0

    @classmethod
    def from_chunks(cls, chunks: list[bytes], where: str = "tablet tape") -> Tape:
        entries: list[list[Any]] = []
        for chunk in chunks:
            entries += parse_chunk(chunk, where)
        return cls(entries, where)

    def calibration(self) -> tuple[str, tuple[int, int], tuple[int, int]] | None:
        """The recorded calibration (device, top-left, bottom-right), None if there was none;
        TapeError if the entry is not one."""
        cal = self.first("calibration")
        if cal is None:
            return None
        try:
            device, corners = cal["device"], (cal["top_left"], cal["bottom_right"])
            if not isinstance(device, str) or not all(
                    isinstance(c, list) and len(c) == 2
                    and all(isinstance(v, int) and abs(v) < 1 << 31 for v in c)
                    for c in corners):
                raise TypeError
        except (KeyError, TypeError):
            raise TapeError(f"{self.where}: the calibration entry is not "
                            "{device, top_left: [x, y], bottom_right: [x, y]}") from None
        return device, tuple(corners[0]), tuple(corners[1])

    def here(self) -> list[tuple[str, Any]]:
        """The entries of the poll the tape is at (those before it dropped)."""
        self._reach(self.poll)
        return self.by_poll.get(self.poll, [])

    def now(self, kind: str) -> list[Any]:
        return [p for k, p in self.here() if k == kind]

    def first(self, kind: str) -> Any:
        """The first ``kind`` entry's payload, from a reading of its own (the recorder notes
        the calibration before the first poll: found at once)."""
        reading = self._entries()
        try:
            for entry in reading:
                if entry[1] == kind:
                    return entry[2]
            return None
        finally:
            _close(reading)

    def opens_now(self) -> dict[str, Any] | None:
        opens = self.now("open")
        return opens[0] if opens else None

    def _entries(self) -> Iterator[list[Any]]:
        records = self._records()
        try:
            for data in records:
                yield from parse_chunk(data, self.where)
        finally:
            _close(records)

    def _reach(self, poll: int) -> None:
        """Drop the polls before ``poll``; read on until an entry past it (or the end)."""
        for old in [p for p in self.by_poll if p < poll]:
            self._held -= len(self.by_poll.pop(old))
        if self._reading is not None and self._pos > self._read:  # a state loaded: go back
            _close(self._reading)
            self._reading = None
        if self._reading is None and not self._ended:
            self._reading, self._pos = self._entries(), 0
        while self._reading is not None and (self._pos < self._read or self._ahead <= poll):
            entry = next(self._reading, None)
            if entry is None:
                self._stop()
                break
            self._pos += 1
            if self._pos <= self._read:  # read before a state was loaded: held there
                continue
            self._read += 1
            self._ahead = entry[0]
            if entry[0] >= poll:
                self.by_poll.setdefault(entry[0], []).append((entry[1], entry[2]))
                self._held += 1
                self._check()

    def _check(self) -> None:
        from camlab88.base import budget

        limit = budget.limit()
        if self._held * ENTRY_BYTES > limit:  # a crafted tape: millions of entries at a poll
            self._stop()
            if self.on_fault is not None:
                self.on_fault(f"{self.where}: poll {self._ahead}: its {self._held:,} entries "
                              f"and more, held at once, would need more than the memory "
                              f"budget of {budget.size_text(limit)} (raise it with camlab88 "
                              f"--budget SIZE or {budget.ENV}=SIZE)")

    def _stop(self) -> None:
        if self._reading is not None:
            _close(self._reading)
        self._reading, self._ended = None, True


def _close(reading: Any) -> None:
    close = getattr(reading, "close", None)
    if close is not None:
        close()  # the file, when read from one


class TapeSource(TabletSource):
    """Replays one opening of the tablet: the same decoder fed the recorded bytes."""

    def __init__(self, tape: Tape, opened: dict[str, Any],
                 make_decoder: Callable[[dict[str, Any]], Any]) -> None:
        self.tape = tape
        self.name = str(opened.get("name", "tablet"))
        self.decoder = make_decoder(opened)
        self.model = self.decoder.model
        if opened.get("kind") == "serial":
            self.clock = lambda: self._level_time
            self.last_data = 0.0
            self.stall_release, self.stall_fallback = 0.5, 2.0
        self._level_time = 0.0

    def read(self, timeout: float = 0.0) -> list[TabletEvent]:
        entries = self.tape.here()
        events: list[TabletEvent] = []
        for kind, payload in entries:
            if kind == "raw":
                events += self.decoder.feed(bytes.fromhex(payload))
            elif kind == "flush":
                events += self.decoder.flush()
            elif kind == "lost":
                raise SourceLost(str(payload))
            elif kind == "idle":
                self._level_time = (0.0, self.stall_release, self.stall_fallback)[int(payload)]
        self.model = self.decoder.model
        return events


class SerialTapeDecoder:
    """The serial parser a recorded opening used, set up as the tablet's replies left it."""

    def __init__(self, opened: dict[str, Any]) -> None:
        from camlab88.protocols.tablets import wacom4
        from camlab88.protocols.tablets.registry import make_parser
        from camlab88.protocols.tablets.serial_source import configure_wacom

        self.parser = make_parser(str(opened["protocol"]), opened.get("options") or {},
                                  parmrk=bool(opened.get("parmrk")))
        if isinstance(self.parser, wacom4.Wacom4Parser):
            configure_wacom(self.parser, [DeviceReply(str(t)) for t in opened.get("replies", [])])
        model = dict(opened["model"])
        if model.get("tilt_range") is not None:
            model["tilt_range"] = tuple(model["tilt_range"])
        self.parser.model = TabletModel(**model)

    @property
    def model(self) -> TabletModel:
        return self.parser.model

    def feed(self, data: bytes) -> list[TabletEvent]:
        return self.parser.feed(data, 0.0)

    def flush(self) -> list[TabletEvent]:
        return self.parser.flush(0.0)
