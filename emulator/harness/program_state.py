"""A program's save state: one versioned envelope around the program's declared state.

The envelope (emulator.machine.state_file, device ``program``) names the program (its
command), the program's state version, the arguments that shape it (files by SHA-256 of
their content, run-only flags left out) and the harness's place (ticks, frames shown, the
next frame's time); its header's ``values`` and its binary parts are the target's declared
state (base.plainstate): plain values checked against the schema the target declares
(``STATE_VERSION``, ``STATE_SCHEMA``, ``state_values()``, ``load_state_values(values)``;
``migrate_state(version, values)`` reads an older version where one is documented). A state
of another program, another state version or other inputs is refused with one line
(MachineStateError). Nothing in a state names code, a class or a path, and loading one does
no I/O but reading the file.

In-process rewind snapshots (F4, a seek's jump) never leave the process: a target that
declares no state keeps them as base.objstate graphs (``snapshot`` / ``rewind``).
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

from camlab88.base.plainstate import Frac, Int, StateValueError, Tuple, decode, encode
from camlab88.emulator.machine.state_file import MachineStateError, pack, unpack

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness

SUFFIX = ".c88state"
# the harness's place: ticks, frames shown, the next frame's time, the last shown's time
PLACE = Tuple((Int(0, 1 << 53), Int(0, 1 << 53), Frac(), Frac()))
TIME = Frac(nonnegative=True)


@dataclass
class StateOptions:
    """``--save-state FILE [--at SECONDS]``, ``--load-state FILE`` and what a state names."""

    save: Path | None = None
    at: Fraction | None = None
    load: Path | None = None
    load_data: bytes | None = None     # a seek's state, made by this process (never a file)
    version: str = "?"
    key_dir: Path = field(default_factory=Path.cwd)  # where F2 writes without --save-state
    snapshot_every: Fraction = Fraction(5)  # s of virtual time between F4 snapshots
    snapshots: list[tuple[Fraction, Any]] | None = None  # kept (and collected) for F4
    seek_to: Fraction | None = None    # a seek's first run: stop here, keep the state ...
    seek_state: Any = None             # ... in here (an in-process snapshot)


class StateNotSaved(Exception):
    """--save-state could not save (one line naming the file): the run's work failed
    (camlab88.cli ends it with status 1)."""


def declares_state(target: Any) -> bool:
    return all(hasattr(target, n) for n in ("STATE_VERSION", "STATE_SCHEMA", "state_values",
                                            "load_state_values"))


# ---------------------------------------------------------------------------- identity
def identity(harness: Harness, version: str) -> dict[str, Any]:
    """What a state needs to be loaded: the program, the version, the shaping arguments."""
    held = getattr(harness.target, "state_holds_files", ())  # (their content is in it)
    argv = [IN_STATE if w in held else w for w in harness.options.argv]
    return {"program": harness.options.command, "camlab88": version,
            "args": shaping_args(argv, harness.options.inputs, harness.options.run_only)}


IN_STATE = "<a file the state holds>"


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
    """One line saying how a state's program or inputs differ from this run's (the camlab88
    version it names is only noted: the program's state version is what must agree)."""
    if head.get("program") != mine["program"]:
        raise MachineStateError(f"it is a state of {_short(head.get('program'))}, not of "
                                f"'{mine['program']}'")
    theirs, ours = head.get("args"), mine["args"]
    if theirs != ours:
        raise MachineStateError("it was saved with other arguments or input files: "
                                f"{_first_difference(theirs, ours)}")


def _first_difference(theirs: Any, ours: list[str]) -> str:
    if not isinstance(theirs, list):
        return "its argument list is damaged"
    for a, b in zip(theirs, ours, strict=False):
        if a != b:
            return f"{_short(a)} there, {_short(b)} here"
    return f"{len(theirs)} arguments there, {len(ours)} here"


# ---------------------------------------------------------------------------- envelope
def save_program(harness: Harness, ident: dict[str, Any]) -> bytes:
    """The whole state now, for a file: ``ident`` (identity(): the program, version and input
    files as they are now), the harness's place, the target's declared state."""
    target = harness.target
    if not declares_state(target):
        raise MachineStateError(f"{ident['program']} does not save its state to a file")
    parts: dict[str, bytes] = {}
    try:
        values = encode(target.STATE_SCHEMA, target.state_values(), parts)
    except (StateValueError, TypeError, ValueError, KeyError) as exc:
        raise MachineStateError(f"cannot save this program's state now: {exc}") from None
    head = dict(ident, state_version=target.STATE_VERSION,
                harness=PLACE.encode(_place(harness), parts),
                time=TIME.encode(target.time(), parts), values=values)
    return pack("program", head, parts)


def _place(harness: Harness) -> tuple[int, int, Fraction, Fraction]:
    return (harness.ticks, harness.frames_shown, harness._next_show, harness._shown_at)


def read_program(data: bytes, harness: Harness, ident: dict[str, Any]
                 ) -> tuple[tuple[int, int, Fraction, Fraction], Fraction, Any]:
    """(place, time, values) of a state file's bytes for ``harness``'s target, every value
    checked against the target's schema; nothing is changed."""
    target = harness.target
    if not declares_state(target):
        raise MachineStateError(f"{ident['program']} does not load a state from a file")
    head, parts = unpack(data, "program")
    check_identity(head, ident)
    version = head.get("state_version")
    values = head.get("values")
    if version != target.STATE_VERSION:
        migrate = getattr(target, "migrate_state", None)
        older = type(version) is int and 0 < version < target.STATE_VERSION
        if migrate is None or not older:
            raise MachineStateError(f"it is a state of version {_short(version)}; this "
                                    f"{ident['program']} reads version "
                                    f"{target.STATE_VERSION}")
        values = migrate(version, values)
    try:
        place = PLACE.decode(head.get("harness"), parts, "harness")
        when = TIME.decode(head.get("time"), parts, "time")
        values = decode(target.STATE_SCHEMA, values, parts, "state")
    except StateValueError as exc:
        raise MachineStateError(str(exc)) from None
    return place, when, values


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def load_program(data: bytes, harness: Harness, ident: dict[str, Any]) -> Fraction:
    """Continue ``harness`` from a state file's bytes (checked against ``ident`` and the
    target's schema first; all or nothing); returns its virtual time."""
    place, when, values = read_program(data, harness, ident)
    _load_values(harness.target, values)
    _put_place(harness, place)
    return when


def _load_values(target: Any, values: Any) -> None:
    """The target's load_state_values (which checks everything before it changes anything);
    what the program refuses is one line."""
    try:
        target.load_state_values(values)
    except MachineStateError:
        raise
    except (ValueError, KeyError, TypeError, IndexError, ArithmeticError) as exc:
        text = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise MachineStateError(f"the program refused it: {text[:300]}") from None


def _put_place(harness: Harness, place: tuple[int, int, Fraction, Fraction]) -> None:
    harness.ticks, harness.frames_shown, harness._next_show, harness._shown_at = place
    harness.last_frame = harness.target.frame() if place[1] else None


# ---------------------------------------------------------------------------- in process
@dataclass(frozen=True)
class Snapshot:
    """A state that never leaves this process (F4, a seek): the target's own in-memory
    state and the harness's place."""

    program: str
    place: tuple[int, int, Fraction, Fraction]
    time: Fraction
    values: Any


def snapshot(harness: Harness) -> Snapshot:
    """The whole state now, in memory: the declared state where the target has one, else
    its object graph (base.objstate: in-process only)."""
    target = harness.target
    # a target whose declared state is its input log (input_log) would run from its start
    # at every F4: its in-memory graph is faster
    if declares_state(target) and not getattr(target, "snapshots_by_graph", False):
        parts: dict[str, bytes] = {}
        try:
            values: Any = ("declared", encode(target.STATE_SCHEMA, target.state_values(),
                                              parts), parts)
        except (TypeError, ValueError, KeyError) as exc:
            raise MachineStateError(f"cannot save this program's state now: {exc}") from None
    else:
        from camlab88.base.objstate import StateError, capture

        try:
            values = ("graph", *capture(target))
        except StateError as exc:
            raise MachineStateError(f"cannot save this program's state now: {exc}") from None
    return Snapshot(harness.options.command, _place(harness), target.time(), values)


def rewind(harness: Harness, snap: Snapshot) -> Fraction:
    """Put a snapshot of this program back (all or nothing); returns its virtual time."""
    if not isinstance(snap, Snapshot) or snap.program != harness.options.command:
        raise MachineStateError("not a snapshot of this program")
    target = harness.target
    kind, *rest = snap.values
    if kind == "declared":
        try:
            values = decode(target.STATE_SCHEMA, rest[0], rest[1], "state")
        except StateValueError as exc:
            raise MachineStateError(str(exc)) from None
        _load_values(target, values)
    else:
        from camlab88.base.objstate import StateError, restore

        try:
            restore(target, rest[0], rest[1])
        except (StateError, KeyError) as exc:
            raise MachineStateError(f"the snapshot does not fit: {exc}") from None
    _put_place(harness, snap.place)
    return snap.time
