"""A program's declared state as the input that made it (kas edit, kas path, kas paint,
snooker camera, ca actors: editors whose models are large object graphs of the user's
work, fed by the window and, for the camera tool, by a file it watches).

The state is plain values (base.plainstate): how many ticks the program has run, every
window event it was given (by the tick it came before), every text it read from outside
while it ran (by tick) and the SHA-256 of the picture then. Loading builds the program from
the command line as usual (its input files are the identity's, by content) and runs it those
ticks again through its own code with those events: virtual time makes that deterministic,
so it ends where the saved run was; the picture is then compared, so a log that does not
rebuild the saved screen is refused. While it runs again the program's own writes are held
back (``rebuilding``): a load does no I/O but reading the state file.

A program fed by a tablet (``--tablet SOURCE``) keeps its tablet's input too (``tablet``): the
tablet tape's entries (protocols/tablets/tape.py: what the device sent, at which poll; the
same entries a ``--record`` keeps as ``T`` records) taken tick by tick, joined into one JSON
list in a binary part (at most ``MAX_TABLET_TAPE`` bytes: a session past that saves no
state), with the tablet's protocol and whether it was the emulated one. A load decodes them
through the same protocol parser as a replay decodes a recording's tape, never reading the
device while the session runs again; then the tablet of this run's command line carries on
(a state never chooses the source). A state holding a tablet's input is refused by a run
without ``--tablet`` or with a tablet of another protocol.

The cost is the session's length: a load runs every tick again (docs/harness.md has the
figures). A state is loaded into a fresh run only (``--load-state``); going back in a run
that has moved on is F4's in-memory snapshots (``snapshots_by_graph`` on the target).
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from camlab88.base.plainstate import (
    Blob,
    Bool,
    Choice,
    Int,
    Kind,
    ListOf,
    Opt,
    Record,
    Str,
    Tuple,
)
from camlab88.emulator.host_input import HostEvent, KeyDown, KeyUp, PointerButton, PointerMove
from camlab88.emulator.machine.state_file import MachineStateError

# a load runs every tick again: its time is bounded by this (about 11 h of a Sigma
# session's line time, 23 h of a Rainbow's; a longer session saves no state)
MAX_TICKS = 1 << 22
MODS = ("shift", "ctrl", "alt", "meta")
_XY = Int(-(1 << 20), 1 << 20)
# (kind, key, char, mods, x, y, button, pressed, buttons held): one shape for every kind
EVENT = Tuple((Choice(("key", "keyup", "move", "button", "close")), Str(32), Str(4),
               ListOf(Choice(MODS), 4), _XY, _XY, Int(0, 7), Bool(), ListOf(Int(1, 7), 3)))
# bytes of a session's tablet tape a state keeps (a streaming tablet's 100 polls a second
# note ~3 KiB/s: about three hours; a session past it saves no state, and a state's part
# claiming more is refused before its JSON is read)
MAX_TABLET_TAPE = 32 << 20
TABLET = Opt(Record(protocol=Str(64), emulated=Bool(), tape=Blob(MAX_TABLET_TAPE)))
SCHEMA = Record(ticks=Int(0, MAX_TICKS), events=ListOf(Tuple((Int(0, MAX_TICKS), EVENT)),
                                                      1 << 20),
                texts=ListOf(Tuple((Int(0, MAX_TICKS), Str(1 << 22))), 4096),
                picture=Str(64), tablet=TABLET)
VERSION_WITH_TABLET = 2  # the editors' state versions that hold ``tablet`` (1: none)


def encode_event(e: HostEvent) -> tuple | None:
    """An event as the log keeps it (None: not the program's: a Quit is the harness's)."""
    if isinstance(e, KeyDown):
        return ("key", e.key, e.char, sorted(e.mods), 0, 0, 0, False, [])
    if isinstance(e, KeyUp):
        return ("keyup", e.key, "", [], 0, 0, 0, False, [])
    if isinstance(e, PointerMove):
        return ("move", "", "", [], e.x, e.y, 0, False, sorted(e.buttons))
    if isinstance(e, PointerButton):
        return ("button", "", "", [], e.x, e.y, e.button, e.pressed, [])
    return None


def decode_event(v: tuple) -> HostEvent | None:
    kind, key, char, mods, x, y, button, pressed, buttons = v
    if kind == "key":
        return KeyDown(key, char, frozenset(mods))
    if kind == "keyup":
        return KeyUp(key)
    if kind == "move":
        return PointerMove(x, y, frozenset(buttons))
    if kind == "button":
        return PointerButton(x, y, button, pressed)
    return None  # "close": the target's may_close, asked again


def picture_hash(frame: np.ndarray, more: bytes = b"") -> str:
    """SHA-256 of a picture and ``more`` (e.g. the machine's own state: what the line
    carried shows there before it shows on the screen)."""
    a = np.ascontiguousarray(frame)
    return hashlib.sha256(repr((a.shape, a.dtype.str)).encode() + a.tobytes() + more
                          ).hexdigest()


class InputLog:
    """What a target was given, tick by tick (see the module's docstring)."""

    def __init__(self) -> None:
        self.ticks = 0
        self.events: list[tuple[int, tuple]] = []
        self.texts: list[tuple[int, str]] = []
        self.rebuilding = False
        self.tablet: TabletKept | None = None  # keep_tablet: the tablet's tape, tick by tick

    def keep_tablet(self, protocol: str, emulated: bool, take: Callable[[], bytes]) -> None:
        """The session is fed by a tablet of ``protocol``: ``take()`` gives its tape's new
        entries (a JSON list, b"" for none), taken at every tick."""
        self.tablet = TabletKept(protocol, emulated, take)

    # ------------------------------------------------------------------ while running
    def given(self, events: list[HostEvent]) -> None:
        for e in events:
            v = encode_event(e)
            if v is not None:
                self.events.append((self.ticks, v))

    def closing(self) -> None:
        """The harness asked the program whether it may close and it said no (it asks
        back: that changed it); a yes ends the run."""
        self.events.append((self.ticks, ("close", "", "", [], 0, 0, 0, False, [])))

    def read(self, text: str) -> None:
        """A text the program read from outside in this tick (fed back at a load)."""
        self.texts.append((self.ticks, text))

    def ticked(self) -> None:
        self.ticks += 1
        if self.tablet is not None and not self.rebuilding:
            self.tablet.keep(self.tablet.take())

    # ------------------------------------------------------------------ state
    def values(self, picture: str) -> dict[str, Any]:
        """``picture``: picture_hash() now."""
        if self.ticks > MAX_TICKS:
            raise MachineStateError(f"the session is longer than the {MAX_TICKS} ticks a "
                                    "state runs again at a load")
        tablet = None if self.tablet is None else self.tablet.values()
        return {"ticks": self.ticks, "events": list(self.events), "texts": list(self.texts),
                "picture": picture, "tablet": tablet}

    def tablet_tape(self, values: dict[str, Any]) -> tuple[list[list[Any]] | None, bool]:
        """The state's tablet tape, checked (entries in poll order; None: the saved session
        had no tablet) and whether it was the emulated tablet; MachineStateError in one line
        if it is damaged or does not fit this run's ``--tablet``."""
        saved = values["tablet"]
        if saved is None:
            return None, False
        mine = None if self.tablet is None else self.tablet.protocol
        if mine is None:
            raise MachineStateError(f"it holds a {saved['protocol']} tablet's input: load it "
                                    "with --tablet SOURCE of that protocol")
        if mine != saved["protocol"]:
            raise MachineStateError(f"it holds a {saved['protocol']} tablet's input; this "
                                    f"run's --tablet is {mine}")
        from camlab88.protocols.tablets.tape import TapeError, parse_chunk

        try:
            entries = parse_chunk(saved["tape"], "state.tablet.tape")
        except TapeError as exc:
            raise MachineStateError(str(exc)) from None
        polls = [e[0] for e in entries]
        if polls != sorted(polls):
            raise MachineStateError("state.tablet.tape: its entries are not in poll order")
        return entries, saved["emulated"]

    def rebuild(self, values: dict[str, Any], handle: Callable[[list[HostEvent]], None],
                tick: Callable[[], bool], close: Callable[[], Any],
                picture: Callable[[], str],
                feed: Callable[[str], None] | None = None) -> None:
        """Run a fresh program ``values["ticks"]`` ticks again with the logged input
        (``handle`` the window events of a tick, ``close`` a close asked, ``feed`` a text
        read from outside, then ``tick``); MachineStateError if it is not fresh, if the log
        does not fit, or if the picture then is not the saved one."""
        if self.ticks or self.events:
            raise MachineStateError("this program loads a state into a fresh run only "
                                    "(F4 steps back within a run)")
        n = values["ticks"]
        events, texts = values["events"], values["texts"]
        for name, log in (("events", events), ("texts", texts)):
            at = [t for t, _ in log]
            if at != sorted(at) or (at and at[-1] >= n):
                raise MachineStateError(f"state.{name}: not in tick order within the "
                                        f"{n} ticks run")
        if texts and feed is None:
            raise MachineStateError("state.texts: this program reads nothing from outside")
        self.rebuilding = True
        if self.tablet is not None:  # kept again as saved; what the tablet noted so far
            self.tablet.reset(values["tablet"])  # (its set-up) is the saved session's
        try:
            self._run_again(n, events, texts, handle, tick, close, feed)
        finally:
            self.rebuilding = False
        if picture() != values["picture"]:
            raise MachineStateError("its input does not rebuild the saved picture (made "
                                    "by another build of the program, or changed)")

    def _run_again(self, n: int, events: list, texts: list, handle: Callable, tick: Callable,
                   close: Callable, feed: Callable | None) -> None:
        e = x = 0
        for t in range(n):
            now: list[HostEvent] = []
            while e < len(events) and events[e][0] == t:
                ev = decode_event(events[e][1])
                if ev is None:  # a close asked: the harness asks before the tick's events
                    close()
                else:
                    now.append(ev)
                e += 1
            while x < len(texts) and texts[x][0] == t:
                feed(texts[x][1])  # (texts is empty unless feed is given)
                x += 1
            handle(now)
            if not tick() and t < n - 1:
                raise MachineStateError(f"the program ends after {t + 1} of the state's "
                                        f"{n} ticks")


class TabletKept:
    """A session's tablet tape, as a state keeps it: the chunks taken tick by tick, at most
    MAX_TABLET_TAPE bytes (a chunk past it is not kept and a save is then refused)."""

    def __init__(self, protocol: str, emulated: bool, take: Callable[[], bytes]) -> None:
        self.protocol, self.emulated, self.take = protocol, emulated, take
        self.chunks: list[bytes] = []
        self.size = 0
        self.over = False

    def keep(self, chunk: bytes) -> None:
        if not chunk or self.over:
            return
        if self.size + len(chunk) > MAX_TABLET_TAPE:  # before it is held
            self.over, self.chunks = True, []
            return
        self.chunks.append(chunk)
        self.size += len(chunk)

    def reset(self, saved: dict[str, Any] | None) -> None:
        """As ``saved`` (a state's ``tablet``) holds it; what was taken until now dropped."""
        self.take()
        self.chunks, self.over = [], False
        self.size = 0
        if saved is not None:
            self.keep(saved["tape"])

    def values(self) -> dict[str, Any]:
        if self.over:
            raise MachineStateError(f"the tablet's input in this session is over the "
                                    f"{MAX_TABLET_TAPE >> 20} MiB a state keeps")
        inner = b",".join(c[1:-1] for c in self.chunks if len(c) > 2)  # JSON lists joined
        return {"protocol": self.protocol, "emulated": self.emulated,
                "tape": b"[" + inner + b"]"}


def migrate_values(version: int, values: Any, has_start: bool) -> Any:
    """An editor's state of an older version (JSON, not yet checked) as this version's:
    1 -> 2 holds no tablet input (``tablet`` null: version 1 refused to save a live
    tablet's session)."""
    if version != 1:
        raise MachineStateError(f"it is a state of version {version}; this program reads "
                                f"version {VERSION_WITH_TABLET} (and migrates version 1)")
    log = values.get("input") if has_start and isinstance(values, dict) else values
    if not isinstance(log, dict) or "tablet" in log:
        raise MachineStateError("state (version 1): its input log is not version 1's")
    log = dict(log, tablet=None)
    return dict(values, input=log) if has_start else log


@dataclass(frozen=True)
class StartState:
    """What a program started from, kept in its state (``schema``: a plainstate kind;
    ``values()`` now; ``load(values)`` starts the fresh program from it instead, before it
    runs again). ``files``: words of the command line whose files the state stands in for,
    so their content is left out of the state's identity (the program rewrites them)."""

    schema: Kind
    values: Callable[[], Any]
    load: Callable[[Any], None]
    files: tuple[str, ...] = ()


def program_schema(start: Kind) -> Record:
    """The state of a program with a start (SigmaProgramTarget.give_start,
    RainbowTarget.keep_input): its input log and its start."""
    return Record(input=SCHEMA, start=start)
