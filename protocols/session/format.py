"""The session recording format, version 1: JSON Lines, one record a line, UTF-8.

A recording holds everything needed to run a program's session again on its own::

    {"type": "header", "format": "camlab88-session", "version": 1,
     "argv": ["kas", "edit", "key.kas", "--script", "s.txt"], "headless": true,
     "hash_every": 10}
    {"type": "file", "name": "s.txt", "sha256": "...", "data": "<base64 of zlib>"}   inputs
    {"type": "event", "tick": 12, "time": "3/25", "event": {"kind": "KeyDown", ...}}
    {"type": "wire", "tick": 12, "dir": ">", "data": "<base64 of zlib>"}   the wire
    {"type": "hash", "frame": 25, "tick": 100, "time": "1", "sha256": "..."}   screen hashes
    {"type": "end", "frames": 130, "ticks": 520, "time": "26/5", "sha256": "..."}

``headless`` says whether the recorded run had no window (a replay makes the program take
the same decisions whether or not it shows a window). ``time`` is virtual time in seconds as
an exact fraction; ``tick`` counts harness ticks. ``event`` is a host input event
(emulator.host_input) as the window delivered it; ``wire`` records every byte the program
and device exchanged (``>`` host to device, ``<`` device to host: the traffic since the
previous record of that direction, up to its tick; ``+`` bytes that came from outside during
that tick, which a replay feeds back in; ``-`` (no data) an outside client left during that
tick and the line hung up, which a replay repeats at the same point among the ``+`` records;
``T`` a tablet tape's entries noted during that tick -- protocols.tablets.tape: what a
``--tablet`` sent, at which poll, and its decoder's setup -- from which a replay decodes the
same reports without opening the tablet). A ``hash`` is the SHA-256 of the shown frame's size
and RGB bytes, every ``hash_every`` frames; ``end`` is always last, so a recording without it
is truncated. A reader refuses other formats and newer versions with the file, line and column.
"""

from __future__ import annotations

import base64
import json
import os
import zlib
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

from camlab88.base.fileerror import FilePlaceError

FORMAT = "camlab88-session"
VERSION = 1
_KEYS: dict[str, dict[str, type | tuple[type, ...]]] = {
    "header": {"format": str, "version": int, "argv": list, "headless": bool,
               "hash_every": int},
    "file": {"name": str, "sha256": str, "data": str},
    "event": {"tick": int, "time": str, "event": dict},
    "wire": {"tick": int, "dir": str, "data": str},
    "hash": {"frame": int, "tick": int, "time": str, "sha256": str},
    "end": {"frames": int, "ticks": int, "time": str, "sha256": str},
}


class SessionFileError(FilePlaceError):
    """A recording that cannot be read: ``path:line:col: what was wrong``."""

    def __init__(self, path: str, line: int, col: int, message: str) -> None:
        # line 0: the file as a whole
        super().__init__(path, line, col, message, where=path if line <= 0 else None)


@dataclass(frozen=True)
class ScreenHash:
    frame: int
    tick: int
    time: Fraction
    sha256: str


@dataclass
class SessionRecording:
    """A whole recording in memory (see the module docstring)."""

    argv: list[str]
    hash_every: int = 10
    headless: bool = True
    files: dict[str, bytes] = field(default_factory=dict)
    events: list[tuple[int, Fraction, dict[str, Any]]] = field(default_factory=list)
    wire: list[tuple[int, str, bytes]] = field(default_factory=list)
    hashes: list[ScreenHash] = field(default_factory=list)
    end: ScreenHash | None = None
    ticks: int = 0
    # a replay's recording (read(path, traffic=False)): events, outside input and hashes
    # are not held (the lists above stay empty) but read again from the file, in order
    body: Callable[[], Iterator[tuple[str, Any]]] | None = field(default=None, repr=False,
                                                                 compare=False)
    # and its tablet tape (``T`` wire records), read again as the replay's polls reach it
    tape_body: Callable[[], Iterator[bytes]] | None = field(default=None, repr=False,
                                                            compare=False)

    def timeline(self) -> Iterator[tuple[str, Any]]:
        """Events ``("event", (tick, time, event))``, outside input ``("wire", (tick, dir,
        data))`` (``+``, ``-``) and screen hashes ``("hash", ScreenHash)`` in the order of the
        file: from the file again for a replay's recording, else from the lists."""
        if self.body is not None:
            return self.body()
        items = [(e[0], 0, ("event", e)) for e in self.events]
        items += [(w[0], 1, ("wire", w)) for w in self.wire if w[1] in "+-"]
        items += [(h.tick, 2, ("hash", h)) for h in self.hashes]
        return iter([item for _t, _k, item in sorted(items, key=lambda x: (x[0], x[1]))])

    def tape_records(self) -> Iterator[bytes]:
        """The tablet tape's records (the data of ``T`` wire records) in file order: from
        the file again for a replay's recording (which keeps none of them), else the list's."""
        if self.tape_body is not None:
            return self.tape_body()
        return iter([data for _t, d, data in self.wire if d == "T"])


def _b64(data: bytes) -> str:
    """Binary data: zlib-compressed, then base64 (wire traffic repeats itself a lot)."""
    return base64.b64encode(zlib.compress(data, 9)).decode("ascii")


def head_records(argv: list[str], hash_every: int, headless: bool,
                 files: dict[str, bytes]) -> list[dict[str, Any]]:
    """The header and the input files' records: what a recording begins with."""
    import hashlib

    out: list[dict[str, Any]] = [{"type": "header", "format": FORMAT, "version": VERSION,
                                  "argv": argv, "headless": headless,
                                  "hash_every": hash_every}]
    out += [{"type": "file", "name": n, "sha256": hashlib.sha256(d).hexdigest(),
             "data": _b64(d)} for n, d in files.items()]
    return out


# a body record's place among those of its tick: events, then wire, then the screen hash
EVENT, WIRE, HASH = 0, 1, 2


def event_record(tick: int, time: Fraction, event: dict[str, Any]) -> dict[str, Any]:
    return {"type": "event", "tick": tick, "time": str(time), "event": event}


def wire_record(tick: int, direction: str, data: bytes) -> dict[str, Any]:
    return {"type": "wire", "tick": tick, "dir": direction, "data": _b64(data)}


def end_record(end: ScreenHash, ticks: int) -> dict[str, Any]:
    r = _hash_record("end", end)
    r["ticks"] = ticks
    r.pop("tick", None)  # the end's tick is its ticks
    return r


def _records(rec: SessionRecording) -> list[dict[str, Any]]:
    out = head_records(rec.argv, rec.hash_every, rec.headless, rec.files)
    body: list[tuple[int, int, dict[str, Any]]] = []
    body += [(t, EVENT, event_record(t, v, e)) for t, v, e in rec.events]
    body += [(t, WIRE, wire_record(t, d, b)) for t, d, b in rec.wire]
    body += [(h.tick, HASH, hash_record(h)) for h in rec.hashes]
    out += [r for _, _, r in sorted(body, key=lambda x: (x[0], x[1]))]
    if rec.end is not None:
        out.append(end_record(rec.end, rec.ticks))
    return out


def hash_record(h: ScreenHash) -> dict[str, Any]:
    return _hash_record("hash", h)


def _hash_record(kind: str, h: ScreenHash) -> dict[str, Any]:
    key = "frame" if kind == "hash" else "frames"
    return {"type": kind, key: h.frame, "tick": h.tick, "time": str(h.time), "sha256": h.sha256}


def line(record: dict[str, Any]) -> bytes:
    """One record as the file holds it: compact JSON and a newline."""
    return json.dumps(record, sort_keys=False, separators=(",", ":")).encode("utf-8") + b"\n"


def dumps(rec: SessionRecording) -> str:
    """The recording as text, one JSON record a line."""
    return b"".join(line(r) for r in _records(rec)).decode("utf-8")


def write(path: str | os.PathLike[str], rec: SessionRecording) -> None:
    """Write atomically (base.atomicfile)."""
    from camlab88.base.atomicfile import write_atomic

    write_atomic(path, dumps(rec).encode("utf-8"))


def read(path: str | os.PathLike[str], traffic: bool = True) -> SessionRecording:
    """Read and check a recording; a bad one raises SessionFileError naming line and column.
    ``traffic=False`` (a replay): the file is read a line at a time and the program/device
    traffic (``>``/``<`` wire records) is checked but not kept, so the memory does not grow
    with the recording's length (base.budget counts what is kept); otherwise the whole file
    is checked against the budget first."""
    from camlab88.base import budget
    from camlab88.protocols.session.parse import parse_stream, stream_lines

    name = os.fspath(path)
    try:
        with open(name, "rb") as fh:
            if traffic:
                budget.check(name, 2 * os.fstat(fh.fileno()).st_size, "reading it")
                raw = fh.read()
            else:
                stamp = _stamp(os.fstat(fh.fileno()))
                rec = parse_stream(stream_lines(fh, name), name, traffic=False)
                where = os.path.abspath(name)  # the replay runs in a scratch directory
                rec.body = lambda: _timeline(name, where, stamp)
                rec.tape_body = lambda: _timeline(name, where, stamp, tape=True)
                return rec
    except OSError as exc:
        raise SessionFileError(name, 0, 0, f"cannot read: {exc.strerror or exc}") from None
    return loads(raw, name)


def _stamp(st: os.stat_result) -> tuple[int, int, int, int]:
    return st.st_dev, st.st_ino, st.st_size, st.st_mtime_ns


def _timeline(name: str, where: str, stamp: tuple[int, int, int, int], tape: bool = False,
              ) -> Iterator[Any]:
    """A replay's second pass over ``name`` (at ``where``), refused if the file is not the
    one the first pass checked (replaced or changed since); ``tape``: a pass for the tablet
    tape's records alone (parse.timeline)."""
    from camlab88.protocols.session.parse import timeline

    try:
        with open(where, "rb") as fh:
            if _stamp(os.fstat(fh.fileno())) != stamp:
                raise SessionFileError(name, 0, 0, "changed while it was replayed")
            yield from timeline((ln[:-1] if ln.endswith(b"\n") else ln for ln in fh), name,
                                tape)
    except OSError as exc:
        raise SessionFileError(name, 0, 0, f"cannot read: {exc.strerror or exc}") from None


def loads(raw: bytes, name: str = "<session>") -> SessionRecording:
    from camlab88.protocols.session.parse import parse_lines

    return parse_lines(raw, name)
