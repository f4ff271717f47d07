"""Harness targets for programs on a Sigma: a program session over the line (KAS's editor
and path fronts) and a terminal fed period by period (KAS's line test).  The terminal on a
line served to outside programs (``sigma run``) is emulator.harness.sigma_line."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np

from camlab88.base.plainstate import Blob, Int, Record
from camlab88.emulator.harness import input_log
from camlab88.emulator.host_input import HostEvent
from camlab88.emulator.machine import SigmaMachine
from camlab88.emulator.machine.state_file import MachineStateError

TICK = Fraction(1, 100)  # a program session's polling period: line time between polls
MAX_PERIOD = 1 << 40  # a line test's periods (a year of 25 fps is < 2**30)


class SigmaSessionRun:
    """A program session on a Sigma machine, run: each ``step`` the keys are struck on the
    terminal's keyboard (they travel up the line), the session polls (``session.step(mouse)``:
    input in, update out, through the machine's port) and the machine moves on ``TICK`` with
    the terminal taking what had arrived at the tick's start (the order the KAS programs have
    always shown).  ``session`` has ``step``, ``due``, ``busy``, ``begin`` and ``front``
    (apps side, duck-typed). A key is named as the keyboard names it
    (protocols.sigma.keyboard)."""

    def __init__(self, machine: SigmaMachine, session: Any) -> None:
        self.machine, self.session = machine, session

    @property
    def terminal(self) -> Any:
        return self.machine.terminal

    def step(self, mouse: list[Any] | tuple = (), keys: list[str] | tuple = ()) -> None:
        self.session.begin()
        for k in keys:
            self.machine.press(k)
        self.session.step(mouse)
        self.machine.tick(TICK, take_first=True)

    def busy(self) -> bool:
        """The screen is not up to date or the line is not quiet (either way)."""
        return bool(self.session.busy() or self.machine.in_flight())

    def run_script(self, events: list[Any], settle: bool = True) -> None:
        self.session.begin()
        i = 0
        while i < len(events):
            mouse, keys, i = self.session.due(events, i)
            self.step(mouse, keys)
        if settle:
            self.settle()

    def settle(self, limit: float = 3600.0) -> None:
        """Run until the screen is up to date and the line is quiet."""
        self.session.begin()
        end = self.machine.now + Fraction(limit)
        while self.busy():
            if self.machine.now > end:
                raise RuntimeError(f"the session did not settle within {limit} s of line time")
            self.step()


class SigmaProgramTarget:
    """A program session on a Sigma machine (KAS's editor and path fronts; see
    ``SigmaSessionRun``).  Window keys named in ``key_names`` (or printable characters) are
    struck on the terminal; the left mouse button is the stylus tip.  A timed ``script``
    (session events) plays first; with ``end_with_script`` the run ends once it has played
    and the screen has settled (at most ``settle_limit`` s more)."""

    fps = 25
    escape_is_a_key = True  # the KAS fronts: Esc cancels, or asks before quitting
    _state_exclude = ("on_input",)  # a replay's listener: kept as set, never saved
    snapshots_by_graph = True  # F4 in memory: a declared state is rebuilt from the start

    def __init__(self, run: SigmaSessionRun, title: str, keys: str,
                 key_names: frozenset[str], script: list[Any], end_with_script: bool,
                 settle_limit: Fraction = Fraction(3600)) -> None:
        self.run, self.session = run, run.session
        self.title, self.keys = title, keys
        self.size = (768, 512)
        self.key_names = key_names
        self.script, self.i = script, 0
        self.end_with_script = end_with_script
        self.settle_limit = settle_limit
        self._mouse: list[Any] = []
        self._keys: list[str] = []
        self._buttons = 0
        self.on_input: Any = None  # told each scripted event as it is given (a web replay)
        self.log = input_log.InputLog()
        pointer = self.session.pointer_source
        if getattr(pointer, "protocol", None) is not None:  # a --tablet: its tape is kept
            self.log.keep_tablet(pointer.protocol, pointer.emulated, pointer.take_state_tape)

    def handle_events(self, events: list[HostEvent]) -> None:
        from camlab88.emulator.host_input import KeyDown, PointerButton, PointerMove
        from camlab88.protocols.tablets.input_layer import MouseSample

        self.log.given(events)
        for ev in events:
            if isinstance(ev, KeyDown):
                if ev.key in self.key_names:
                    self._keys.append(ev.key)
                elif len(ev.char) == 1 and 0x20 <= ord(ev.char) <= 0x7E:
                    self._keys.append(ev.char)
            elif isinstance(ev, PointerButton | PointerMove):
                if isinstance(ev, PointerButton) and ev.button == 1:
                    self._buttons = 1 if ev.pressed else 0
                elif isinstance(ev, PointerMove):
                    self._buttons = 1 if 1 in ev.buttons else 0
                self._mouse.append(MouseSample(ev.x, ev.y, self._buttons, self.size))

    def tick(self) -> bool:
        mouse, keys = [], []
        if self.i < len(self.script):
            first = self.i
            mouse, keys, self.i = self.session.due(self.script, self.i)
            if self.on_input is not None and not self.log.rebuilding:
                for ev in self.script[first:self.i]:
                    if ev.kind != "wait":
                        self.on_input(ev)
        self.run.step(mouse + self._mouse, keys + self._keys)
        self._mouse, self._keys = [], []
        self.log.ticked()
        if getattr(self.session.front, "quitting", False):
            return False  # the program was asked to quit (Esc) and may
        return not (self.end_with_script and self.settled())

    def settled(self) -> bool:
        """The script has played and the screen is up to date (the line quiet)."""
        if self.i < len(self.script):
            return False
        if self.run.busy() and self.time() > self._script_end() + self.settle_limit:
            raise ValueError(f"the session did not settle within {self.settle_limit} s of "
                             "line time")
        return not self.run.busy()

    def _script_end(self) -> Fraction:
        return self.script[-1].t if self.script else Fraction(0)

    def frame(self) -> np.ndarray:
        return self.run.machine.frame()

    def time(self) -> Fraction:
        return self.run.machine.now

    def may_close(self) -> bool:
        ok = bool(self.session.front.may_close())
        if not ok:  # the front asks back: part of the session's input
            self.log.closing()
        return ok

    # its declared state (program_state): the input that made it (emulator.harness.
    # input_log: version 2 holds a --tablet's tape; migrate_state reads 1) and, where the
    # command gives one (``start``), what the program started from that its own files no
    # longer hold (kas edit: the keyframe, which F2 rewrites); a load runs a fresh session
    # again with it, the program's writes held back and the tablet read from the tape
    STATE_VERSION = input_log.VERSION_WITH_TABLET
    STATE_SCHEMA: Any = input_log.SCHEMA
    start: input_log.StartState | None = None

    def picture(self) -> str:
        return input_log.picture_hash(self.frame(), self.run.machine.save_state())

    def give_start(self, start: input_log.StartState) -> None:
        self.start = start
        self.STATE_SCHEMA = input_log.program_schema(start.schema)
        self.state_holds_files = start.files

    def migrate_state(self, version: int, values: Any) -> Any:
        return input_log.migrate_values(version, values, self.start is not None)

    def state_values(self) -> dict[str, Any]:
        values = self.log.values(self.picture())
        return values if self.start is None else {"input": values,
                                                  "start": self.start.values()}

    def load_state_values(self, values: dict[str, Any]) -> None:
        if self.start is not None:
            if self.log.ticks:
                raise MachineStateError("this program loads a state into a fresh run only")
            self.start.load(values["start"])
            values = values["input"]
        front, live = self.session.front, self.session.pointer_source
        stand_in = self._tablet_stand_in(values)
        front.rebuilding = True  # the front's saves write nothing while it runs again
        try:
            self.log.rebuild(values, self.handle_events, self.tick, self.may_close,
                             self.picture)
        finally:
            front.rebuilding = False
            self.session.pointer_source = live
        if stand_in is not None:
            try:
                live.carry_on_from(stand_in)
            except ValueError as exc:
                raise MachineStateError(str(exc)) from None
        self._sent_at = len(self.session.sent)  # a recording starts from here

    def _tablet_stand_in(self, values: dict[str, Any]) -> Any:
        """Where this run has a --tablet: what the session polls while it runs again (the
        state's tablet tape, or the mouse where the saved session had no tablet), put in
        place; None without one (a state holding a tablet's input is then refused)."""
        entries, emulated = self.log.tablet_tape(values)
        if self.log.tablet is None:
            return None
        try:
            stand_in = self.session.pointer_source.stand_in(entries, emulated)
        except ValueError as exc:
            raise MachineStateError(str(exc)) from None
        self.session.pointer_source = stand_in
        return stand_in

    def wire(self) -> list[tuple[str, bytes]]:
        """The program's bytes to the terminal since the last call, and the tablet tape's
        new entries (``T``: what a ``--tablet`` sent, for the replay to decode again)."""
        sent = self.session.sent[getattr(self, "_sent_at", 0):]
        self._sent_at = len(self.session.sent)
        out = [(">", b"".join(data for _t, data in sent))]
        take_tape = getattr(self.session.pointer_source, "take_tape", None)
        if take_tape is not None:
            out.append(("T", take_tape()))
        return out


class PeriodTarget:
    """A machine run period by period by a generator (KAS's line test, through
    sigma_batch.host_periods): each tick takes one period (``next(periods)`` runs the
    machine and yields its index); the generator's return value is kept in ``result``.

    Its state: the period reached and the machine. A generator cannot be saved, so loading
    one builds the machine and the program's generator again (``restart() -> (machine,
    periods)``) and runs them to the saved period (deterministic, on virtual time); the
    machine then takes the saved state. A load is all or nothing: the machine's state is
    checked first and the new build replaces the running one only once it is in place (a
    target still at its start, or one that cannot restart, runs its own build on)."""

    keys = "Esc or close the window to stop"

    def __init__(self, machine: SigmaMachine, periods: Any, fps: float, title: str,
                 restart: Any = None) -> None:
        self.machine, self.periods, self.title = machine, periods, title
        self.restart = restart
        self._period = Fraction(fps).limit_denominator(10000)
        self.fps = self._period  # exact, so every period is shown
        self.size = (768, 512)
        self.k = 0
        self.result: Any = None

    def handle_events(self, events: list[HostEvent]) -> None:
        """The line test takes no input (closing the window stops it)."""

    def tick(self) -> bool:
        try:
            self.k = next(self.periods) + 1
        except StopIteration as done:
            self.result = done.value
            return False
        return True

    def frame(self) -> np.ndarray:
        return self.machine.frame()

    def time(self) -> Fraction:
        return self.k / self._period

    # its declared state (program_state): the period reached and the machine's own
    # versioned state; the program's generator is made again and run to that period.
    # Version 2: the period is ``period`` (version 1 called it ``k``) and bounded, so a
    # state cannot ask for more periods than a run could reach (migrate_state reads 1)
    STATE_VERSION = 2
    STATE_SCHEMA = Record(period=Int(0, MAX_PERIOD), machine=Blob())

    def state_values(self) -> dict[str, Any]:
        if self.result is not None:
            raise MachineStateError("the line test has finished: nothing left to save")
        return {"period": self.k, "machine": self.machine.save_state()}

    @staticmethod
    def migrate_state(version: int, values: Any) -> Any:
        """An older version's values (JSON, not yet checked) as this version's: 1 -> 2
        renames ``k`` to ``period`` (the schema then checks its new bound)."""
        if version == 1:
            if not isinstance(values, dict) or set(values) != {"k", "machine"}:
                raise MachineStateError("state (version 1): its fields are not k and "
                                        "machine")
            return {"period": values["k"], "machine": values["machine"]}
        raise MachineStateError(f"no migration from version {version}")

    def load_state_values(self, values: dict[str, Any]) -> None:
        k, state = values["period"], values["machine"]
        self.machine.check_state(state)  # refused here: nothing has run
        at_start = self.k == 0 and self.result is None
        if at_start or (self.restart is None and k >= self.k and self.result is None):
            machine, periods, at = self.machine, self.periods, self.k
        elif self.restart is None:
            raise MachineStateError("this line test cannot go back")
        else:  # a build of its own, in place of the running one once the state is in it
            (machine, periods), at = self.restart(), 0
        while at < k:  # the program's generator run to the saved period
            try:
                at = next(periods) + 1
            except StopIteration:
                raise MachineStateError(f"the line test ends before period {k}") from None
        machine.load_state(state)
        self.machine, self.periods, self.k, self.result = machine, periods, at, None
