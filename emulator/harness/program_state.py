"""A program's save state: one versioned envelope around the target's own state.

The envelope (emulator.machine.state_file, device ``program``) names the program (its
command), the camlab88 version, the arguments that shape it (files by SHA-256 of their
content, run-only flags left out) and the harness's place (ticks, frames shown, the next
frame's time); its blob ``target`` is what ``target.save_state()`` gave. A state of another
program, another version or other inputs is refused with one line (MachineStateError).

Targets save themselves through :class:`SavesState` (the whole object graph from the
target down: device, line, clock, program, tablet decoder; base.objstate); a target without
``save_state`` is captured the same way by :func:`target_state`.
"""

from __future__ import annotations

import hashlib
from contextvars import ContextVar
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

from camlab88.base.objstate import StateError, capture, own_state, restore
from camlab88.emulator.machine.state_file import MachineStateError, pack, unpack
from camlab88.emulator.sigma import Terminal

own_state(Terminal)  # the terminal's own versioned state (emulator/sigma/state.py)

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness

SUFFIX = ".c88state"


@dataclass
class StateOptions:
    """``--save-state FILE [--at SECONDS]``, ``--load-state FILE`` and what a state names."""

    save: Path | None = None
    at: Fraction | None = None
    load: Path | None = None
    load_data: bytes | None = None     # a state in memory (a seek's second run)
    version: str = "?"
    key_dir: Path = field(default_factory=Path.cwd)  # where F2 writes without --save-state
    snapshot_every: Fraction = Fraction(5)  # s of virtual time between F4 snapshots
    snapshots: list[tuple[Fraction, bytes]] | None = None  # kept (and collected) for F4
    seek_to: Fraction | None = None    # a seek's first run: stop here, keep the state ...
    seek_state: bytes | None = None    # ... in here


class SavesState:
    """``save_state()`` / ``load_state(data)`` for a harness target: its whole object graph
    (base.objstate), restored in place into a freshly built target of the same program."""

    def save_state(self) -> bytes:
        return object_state(self)

    def load_state(self, data: bytes) -> None:
        load_object_state(self, data)


def object_state(obj: Any) -> bytes:
    try:
        tree, blobs = capture(obj)
    except StateError as exc:
        raise MachineStateError(f"cannot save this program's state now: {exc}") from None
    return pack("target", {"tree": tree, "class": type(obj).__qualname__},
                {str(i): b for i, b in enumerate(blobs)})


# the command line's words while a state loads: strings a state may not replace
PINNED: ContextVar[frozenset[str]] = ContextVar("camlab88_pinned", default=frozenset())


def load_object_state(obj: Any, data: bytes) -> None:
    head, blobs = unpack(data, "target")
    if head.get("class") != type(obj).__qualname__:
        raise MachineStateError(f"the state is of a {head.get('class')!r}, this program runs "
                                f"a {type(obj).__qualname__!r}")
    try:
        restore(obj, head.get("tree"), [blobs[str(i)] for i in range(len(blobs))],
                pinned=PINNED.get())
    except (StateError, KeyError) as exc:
        raise MachineStateError(f"the state does not fit: {exc}") from None


def target_state(target: Any) -> bytes:
    save = getattr(target, "save_state", None)
    return save() if save is not None else object_state(target)


def load_target_state(target: Any, data: bytes) -> None:
    load = getattr(target, "load_state", None)
    if load is not None:
        load(data)
    else:
        load_object_state(target, data)


# ---------------------------------------------------------------------------- identity
def identity(harness: Harness, version: str) -> dict[str, Any]:
    """What a state needs to be loaded: the program, the version, the shaping arguments."""
    return {"program": harness.options.command, "camlab88": version,
            "args": shaping_args(harness.options.argv, harness.options.inputs,
                                 harness.options.run_only)}


def shaping_args(argv: list[str], extra: list[Path], run_only: dict[str, int]) -> list[str]:
    """``argv`` without its ``run_only`` flags (flag -> how many values it takes: those
    that change how a run is shown or recorded, never what the program does, as the
    command's parser declares them); each word naming a file stands for its content."""
    out: list[str] = []
    skip = 0
    for word in argv:
        if skip:
            skip -= 1
            continue
        name, eq, value = word.partition("=")
        if name in run_only:
            skip = 0 if eq else run_only[name]
            continue
        out.append(_by_content(word))
    return out + [_by_content(str(p)) for p in extra]


def _file_name(word: str) -> bool:
    """A command-line word that names a file (has a directory or a suffix; not a number)."""
    if word.startswith("-") or not ("/" in word or "." in word):
        return False
    try:
        float(word)
    except ValueError:
        return True
    return False


def _by_content(word: str) -> str:
    name, eq, value = word.partition("=") if word.startswith("--") else ("", "", word)
    path = Path(value)
    try:
        if value and path.is_file():
            return f"{name}{eq}<file sha256:{hashlib.sha256(path.read_bytes()).hexdigest()}>"
    except OSError:
        pass
    return word


def check_identity(head: dict[str, Any], mine: dict[str, Any]) -> None:
    """One line saying how a state's program, version or inputs differ from this run's."""
    if head.get("program") != mine["program"]:
        raise MachineStateError(f"it is a state of '{head.get('program')}', not of "
                                f"'{mine['program']}'")
    if head.get("camlab88") != mine["camlab88"]:
        raise MachineStateError(f"it was saved by camlab88 {head.get('camlab88')}; this is "
                                f"camlab88 {mine['camlab88']}")
    theirs, ours = head.get("args"), mine["args"]
    if theirs != ours:
        raise MachineStateError("it was saved with other arguments or input files: "
                                f"{_first_difference(theirs, ours)}")


def _first_difference(theirs: Any, ours: list[str]) -> str:
    if not isinstance(theirs, list):
        return "its argument list is damaged"
    for a, b in zip(theirs, ours, strict=False):
        if a != b:
            return f"{a!r} there, {b!r} here"
    return f"{len(theirs)} arguments there, {len(ours)} here"


# ---------------------------------------------------------------------------- envelope
def save_program(harness: Harness, ident: dict[str, Any]) -> bytes:
    """The whole state now: ``ident`` (identity(): the program, version and input files as
    they are now), the harness's place, the target's state."""
    head = dict(ident, harness=_place(harness),
                time=str(harness.target.time()))
    return pack("program", head, {"target": target_state(harness.target)})


def _place(harness: Harness) -> list[Any]:
    return [harness.ticks, harness.frames_shown, str(harness._next_show),
            str(harness._shown_at)]


def read_program(data: bytes, ident: dict[str, Any] | None
                 ) -> tuple[dict[str, Any], bytes]:
    head, blobs = unpack(data, "program")
    if ident is not None:  # None: a state this run made itself (F3, F4)
        check_identity(head, ident)
    if "target" not in blobs:
        raise MachineStateError("the state holds no program state")
    return head, blobs["target"]


def load_program(data: bytes, harness: Harness, ident: dict[str, Any] | None) -> Fraction:
    """Continue ``harness`` from a state (checked against ``ident`` first); returns its
    virtual time."""
    head, target = read_program(data, ident)
    try:
        ticks, shown, next_show, shown_at = head["harness"]
        place = (int(ticks), int(shown), Fraction(next_show), Fraction(shown_at))
        when = Fraction(head["time"])
    except (KeyError, TypeError, ValueError, ZeroDivisionError) as exc:
        raise MachineStateError(f"the harness's place is damaged: {exc!r}") from None
    words = {w for a in harness.options.argv for w in (a, a.partition("=")[2]) if _file_name(w)}
    token = PINNED.set(frozenset(words))
    try:
        load_target_state(harness.target, target)
    finally:
        PINNED.reset(token)
    harness.ticks, harness.frames_shown, harness._next_show, harness._shown_at = place
    harness.last_frame = harness.target.frame() if place[1] else None
    return when
