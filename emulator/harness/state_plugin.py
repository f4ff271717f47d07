"""Save states in the harness: ``--save-state FILE`` (on quit, or ``--at SECONDS`` of
virtual time), ``--load-state FILE``, and the window keys F2 (save a state, naming the
file), F3 (load the last saved) and F4 (step back one snapshot and play on).

Snapshots for F4 are taken every ``StateOptions.snapshot_every`` seconds of virtual time (5)
and kept in memory, at most ``KEEP`` of them (the oldest are thinned out, so memory stays
bounded however long a run lasts). A program that uses F2-F4 itself (the KAS editor's F2
saves its keyframe) keeps them: there the state keys are Shift+F2, Shift+F3, Shift+F4.
While a session is being recorded (``--record``) F3 and F4 are refused: a recording cannot
go back in time.
"""

from __future__ import annotations

import sys
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING

from camlab88.base.atomicfile import write_atomic
from camlab88.emulator.harness.loop import Plugin
from camlab88.emulator.harness.program_state import (
    SUFFIX,
    StateNotSaved,
    StateOptions,
    declares_state,
    identity,
    load_program,
    rewind,
    save_program,
    snapshot,
)
from camlab88.emulator.harness.written import tell_written
from camlab88.emulator.host_input import HostEvent, KeyDown
from camlab88.emulator.machine.state_file import MachineStateError

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness

KEEP = 64  # snapshots held for F4
MAX_STATE_FILE = 64 << 20  # bytes (emulator.machine.state_file.MAX_FILE)


def read_state_file(command: str, path: Path) -> bytes:
    """A state file's bytes, at most MAX_STATE_FILE of them (read no further): the only I/O
    a load does."""
    try:
        with open(path, "rb") as f:
            data = f.read(MAX_STATE_FILE + 1)
    except OSError as exc:
        raise SystemExit(f"{command}: cannot read {path}: {exc.strerror or exc}") from None
    if len(data) > MAX_STATE_FILE:
        raise SystemExit(f"{command}: {path}: not loaded: larger than {MAX_STATE_FILE} bytes")
    return data


class StatePlugin(Plugin):
    """Loads a state before the first tick; saves at ``--at`` or at the end; the keys."""

    keys = [("F2", "save state"), ("F3", "load last saved state"),
            ("F4", "step back one snapshot")]

    def __init__(self, options: StateOptions) -> None:
        self.options = options
        self.saved_at_time = False
        self.last_saved: bytes | None = None
        # a seek collects its snapshots into options.snapshots (shared: the replay keeps them)
        self.snapshots: list[tuple[Fraction, bytes]] = (
            options.snapshots if options.snapshots is not None else [])
        self._next_snapshot = Fraction(0)
        self.written: list[Path] = []
        self.refused = False  # the run was refused at its start: nothing to say at its end
        self._identity: dict | None = None

    # ------------------------------------------------------------------ start / end
    def start(self, harness: Harness) -> None:
        o = self.options
        if (o.save is not None or o.load is not None) and not declares_state(harness.target):
            flag = "--save-state" if o.save is not None else "--load-state"
            self.refused = True
            raise SystemExit(f"{harness.options.command}: {flag}: this program does not "
                             "declare its state yet, so it saves and loads none (F4 rewinds)")
        if o.save is not None or o.load is not None:
            self._identity = identity(harness, o.version)  # the inputs as the run began
        if o.load_data is not None:  # a seek: this process's own snapshot
            try:
                self._next_snapshot = rewind(harness, o.load_data)
            except MachineStateError as exc:
                raise SystemExit(f"{harness.options.command}: the state to start from: not "
                                 f"loaded: {exc}") from None
        elif o.load is not None:
            data = read_state_file(harness.options.command, Path(o.load))
            try:
                when = load_program(data, harness, self._identity)
            except MachineStateError as exc:
                raise SystemExit(f"{harness.options.command}: {o.load}: not loaded: "
                                 f"{exc}") from None
            self.last_saved = data
            self._next_snapshot = when

    def post_tick(self, harness: Harness) -> None:
        now = harness.target.time()
        o = self.options
        if o.save is not None and o.at is not None and not self.saved_at_time and now >= o.at:
            self.saved_at_time = True
            self._write(harness, Path(o.save), asked=True)
        if o.seek_to is not None and now >= o.seek_to:  # a seek's first run ends here ...
            try:
                o.seek_state = snapshot(harness)
                harness.stop()
            except MachineStateError:
                pass  # ... or at the first tick after it with a state (e.g. a dialogue ended)
        elif (harness.window is not None or o.snapshots is not None) and \
                now >= self._next_snapshot:
            self._snapshot(harness, now)

    def finish(self, harness: Harness) -> None:
        o = self.options
        if self.refused:
            return
        if o.save is not None and o.at is None:
            self._write(harness, Path(o.save), asked=True)
        elif o.save is not None and not self.saved_at_time:
            print(f"{harness.options.command}: --save-state: the run ended at "
                  f"{float(harness.target.time()):g} s, before --at {float(o.at or 0):g} s; "
                  "no state saved", file=sys.stderr)

    # ------------------------------------------------------------------ the keys
    def handle_events(self, harness: Harness, events: list[HostEvent]) -> list[HostEvent]:
        own = {k.lower() for k in getattr(harness.target, "key_names", ())}
        out: list[HostEvent] = []
        for ev in events:
            action = _state_key(ev, own)
            if action is None:
                out.append(ev)
            else:
                action(self, harness)
        return out

    def save_key(self, harness: Harness) -> None:
        path = Path(self.options.save) if self.options.save is not None else self._free_name(
            harness)
        self._write(harness, path)

    def load_key(self, harness: Harness) -> None:
        if self._refuse_going_back(harness, "F3") or self.last_saved is None:
            if self.last_saved is None:
                _say(harness, "F3: no state saved yet (F2 saves one)")
            return
        self._load(harness, self.last_saved, "F3: loaded the last saved state")

    def back_key(self, harness: Harness) -> None:
        if self._refuse_going_back(harness, "F4"):
            return
        now = harness.target.time()
        older = [s for s in self.snapshots if s[0] < now]
        if not older:
            _say(harness, "F4: no earlier snapshot")
            return
        when, snap = older[-1]
        self.snapshots[:] = older[:-1]
        try:
            self._next_snapshot = rewind(harness, snap)
        except MachineStateError as exc:
            _say(harness, f"F4: not loaded: {exc}")
            return
        self._shown(harness, f"F4: back to {float(when):g} s")

    # ------------------------------------------------------------------ helpers
    def _refuse_going_back(self, harness: Harness, key: str) -> bool:
        if harness.options.record is None:
            return False
        _say(harness, f"{key}: refused while recording (a recording cannot go back in time)")
        return True

    def _load(self, harness: Harness, data: bytes, said: str) -> None:
        try:
            when = load_program(data, harness, self._ident(harness))
        except MachineStateError as exc:
            _say(harness, f"not loaded: {exc}")
            return
        self._next_snapshot = when
        self._shown(harness, said)

    def _shown(self, harness: Harness, said: str) -> None:
        if harness.window is not None and harness.last_frame is not None:
            harness.window.show(harness.last_frame)
        _say(harness, said)

    def _snapshot(self, harness: Harness, now: Fraction) -> None:
        try:
            snap = snapshot(harness)
        except MachineStateError:
            return  # e.g. mid-dialogue: the next tick tries again
        self.snapshots.append((now, snap))
        if len(self.snapshots) > KEEP:  # thin out: every other one of the older half
            half = len(self.snapshots) // 2
            self.snapshots[:] = self.snapshots[:half:2] + self.snapshots[half:]
        self._next_snapshot = now + self.options.snapshot_every

    def _write(self, harness: Harness, path: Path, asked: bool = False) -> None:
        """Save to ``path``; a state that cannot be made or written is said in one line, and
        with ``asked`` (--save-state) the run ends with status 1 (docs/exit_status.md)."""
        try:
            data = save_program(harness, self._ident(harness))
            write_atomic(path, data)
        except (MachineStateError, OSError) as exc:
            why = exc.strerror or exc if isinstance(exc, OSError) else exc
            said = f"--save-state {path}: no state saved at " \
                f"{float(harness.target.time()):g} s: {why}"
            if asked:
                raise StateNotSaved(f"{harness.options.command}: {said}") from None
            _say(harness, said)
            return
        self.last_saved = data
        self.written.append(path)
        tell_written(harness, f"saved state {path} (at {float(harness.target.time()):g} s)")

    def _ident(self, harness: Harness) -> dict:
        """The run's identity: its command line with its input files by content, hashed
        once, when the run began (with --save-state or --load-state), or at the first F2."""
        if self._identity is None:
            self._identity = identity(harness, self.options.version)
        return self._identity

    def _free_name(self, harness: Harness) -> Path:
        stem = "-".join(harness.options.command.split()[1:]) or "state"
        for n in range(1, 10000):
            path = self.options.key_dir / f"{stem}-{n:03d}{SUFFIX}"
            if not path.exists():
                return path
        return self.options.key_dir / f"{stem}-last{SUFFIX}"


_ACTIONS = {"f2": StatePlugin.save_key, "f3": StatePlugin.load_key,
            "f4": StatePlugin.back_key}


def _state_key(ev: HostEvent, own: set[str]):  # the plugin method for a state key, or None
    if not isinstance(ev, KeyDown) or ev.key not in _ACTIONS:
        return None
    if ev.key in own and "shift" not in ev.mods:
        return None  # the program's own key
    return _ACTIONS[ev.key]


def _say(harness: Harness, text: str) -> None:
    print(f"{harness.options.command}: {text}", file=sys.stderr, flush=True)
