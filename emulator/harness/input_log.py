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

from camlab88.base.plainstate import Bool, Choice, Int, Kind, ListOf, Record, Str, Tuple
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
SCHEMA = Record(ticks=Int(0, MAX_TICKS), events=ListOf(Tuple((Int(0, MAX_TICKS), EVENT)),
                                                      1 << 20),
                texts=ListOf(Tuple((Int(0, MAX_TICKS), Str(1 << 22))), 4096),
                picture=Str(64))


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

    # ------------------------------------------------------------------ state
    def values(self, picture: str) -> dict[str, Any]:
        """``picture``: picture_hash() now."""
        if self.ticks > MAX_TICKS:
            raise MachineStateError(f"the session is longer than the {MAX_TICKS} ticks a "
                                    "state runs again at a load")
        return {"ticks": self.ticks, "events": list(self.events), "texts": list(self.texts),
                "picture": picture}

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
