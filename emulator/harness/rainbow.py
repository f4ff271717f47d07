"""The harness target for a program on a Rainbow machine (snooker, CA, the Rainbow demo,
and new Rainbow programs).  One tick = one program step, normally one 1/50 s display frame.
"""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction
from typing import Any

import numpy as np

from camlab88.base.plainstate import Blob, Int, Opt, Record, Tuple
from camlab88.emulator.harness import input_log
from camlab88.emulator.host_input import HostEvent
from camlab88.emulator.machine import RainbowMachine
from camlab88.emulator.machine.state_file import MachineStateError
from camlab88.emulator.rainbow.host_input import RainbowHostInput
from camlab88.protocols.rainbow.script import Player

FPS = 50  # the Rainbow's display frames per second
# the state of a program kept by its input (keep_input): version 2 holds a --tablet's
# tape (input_log; migrate_state reads 1)
INPUT_STATE_VERSION = input_log.VERSION_WITH_TABLET


class RainbowTarget:
    """``step()`` advances the program (True while it runs).  Window input goes to the
    device's input controller; with a ``script`` (protocols.rainbow.script.Player) the
    script drives the mouse and keyboard instead (and, with ``end_with_script``, the run
    ends with it; in a window the program carries on until it is closed)."""

    fps = FPS
    size = (768, 576)
    escape_is_a_key = False  # True where the program reads Esc itself (the harness: quit)
    _state_exclude = ("on_input",)  # a replay's listener: kept as set, never saved

    def __init__(self, machine: RainbowMachine, step: Callable[[], bool], title: str, keys: str,
                 script: Player | None = None, end_with_script: bool = True,
                 status: Callable[[], str] | None = None, program: Any = None) -> None:
        self.machine = machine
        self.step = step
        self.title = title
        self.keys = keys
        self.script = script
        self.end_with_script = end_with_script
        if status is not None:  # the harness's optional title-bar status
            self.status = status
        self.host = RainbowHostInput()
        self._wire_at = 0
        self.tablet: Any = None  # a tablet source the command polls in its step
        self.on_input: Callable[[Any], None] | None = None  # told each scripted event
        self.log = input_log.InputLog()  # a state of the input that made it (keep_input)
        self._kept: tuple[Any, Any] | None = None
        if program is not None:  # it declares its state: so does the target
            self.program = program
            self.STATE_VERSION = program.STATE_VERSION
            self.STATE_SCHEMA = target_schema(program.STATE_SCHEMA)
            if hasattr(program, "migrate_state"):  # it reads its older versions
                self.migrate_state = self._migrate_program

    # ------------------------------------------------------------------ declared state
    def keep_input(self, start: input_log.StartState | None = None,
                   rebuilding: Callable[[bool], None] | None = None,
                   feed: Callable[[str], None] | None = None) -> None:
        """A program that declares no state of its own (an editor: the camera tool, the
        actors editor): its state is the input that made it (emulator.harness.input_log),
        with what it started from (``start``). ``rebuilding(True)`` before a load runs it
        again (its writes held back, its outside reads taken from ``feed``), ``(False)``
        after."""
        self._kept = (start, rebuilding)
        self._feed = feed
        self.STATE_VERSION = INPUT_STATE_VERSION
        self.migrate_state = self._migrate_input
        if self.tablet is not None:  # a --tablet (set before): its tape is kept
            self.tablet.keep_for_state()
            self.log.keep_tablet(self.tablet.protocol, False, self.tablet.take_state_tape)
        self.STATE_SCHEMA = input_log.SCHEMA if start is None else \
            input_log.program_schema(start.schema)
        self.snapshots_by_graph = True  # F4 in memory: rebuilding runs from the start
        if start is not None:
            self.state_holds_files = start.files

    def asks_before_closing(self, may_close: Callable[[], bool]) -> None:
        """The program's answer to a close (a no asks back: part of its input)."""
        def asked() -> bool:
            ok = bool(may_close())
            if not ok:
                self.log.closing()
            return ok
        self.may_close = asked

    def picture(self) -> str:
        return input_log.picture_hash(self.frame(), self.machine.session_state())

    def state_values(self) -> dict[str, Any]:
        """The Rainbow and its client (RainbowMachine.session_state), the script's place,
        the window's mouse buttons and the program's own declared state (or keep_input's
        log)."""
        if self._kept is not None:
            return self._input_values()
        script = None if self.script is None else (
            self.script.played(), self.script.wait)
        return {"rainbow": self.machine.session_state(), "script": script,
                "buttons": self.host.buttons, "program": self.program.state_values()}

    def _migrate_program(self, version: int, values: Any) -> Any:
        """An older version's values (JSON, unchecked): the program migrates its own part."""
        if not isinstance(values, dict) or "program" not in values:
            raise MachineStateError(f"state (version {version}): it holds no program part")
        try:
            return dict(values, program=self.program.migrate_state(version,
                                                                    values["program"]))
        except ValueError as exc:
            raise MachineStateError(f"state (version {version}): {exc}") from None

    def _migrate_input(self, version: int, values: Any) -> Any:
        return input_log.migrate_values(version, values, self._kept[0] is not None)

    def _input_values(self) -> dict[str, Any]:
        values = self.log.values(self.picture())
        start = self._kept[0] if self._kept else None
        return values if start is None else {"input": values, "start": start.values()}

    def _load_input(self, values: dict[str, Any]) -> None:
        start, rebuilding = self._kept or (None, None)
        if start is not None:
            if self.log.ticks:
                raise MachineStateError("this program loads a state into a fresh run only")
            start.load(values["start"])
            values = values["input"]
        entries, _ = self.log.tablet_tape(values)
        live = self.tablet
        if live is not None:  # the program reads the state's tape while it runs again
            self.tablet = live.stand_in(entries)
        stand_in = self.tablet
        if rebuilding is not None:
            rebuilding(True)
        try:
            self.log.rebuild(values, self.handle_events, self.tick,
                             getattr(self, "may_close", lambda: True), self.picture,
                             self._feed)
        finally:
            self.tablet = live
            if rebuilding is not None:
                rebuilding(False)
        if live is not None:
            try:
                live.carry_on_from(stand_in)
            except ValueError as exc:
                raise MachineStateError(str(exc)) from None
        rec = self.machine.recording
        self._wire_at = len(rec.entries) if rec is not None else 0  # a recording from here

    def load_state_values(self, values: dict[str, Any]) -> None:
        """Continue from state_values() (checked against STATE_SCHEMA): every part is
        checked before anything changes."""
        if self._kept is not None:
            self._load_input(values)
            return
        put_rainbow = self.machine.check_session_state(values["rainbow"])
        script = values["script"]
        if (script is None) != (self.script is None) or (
                script is not None and not self.script.can_resume(*script)):
            raise MachineStateError("the state's place in the --events script does not fit "
                                    "this run's script")
        put_program = self.program.check_state_values(values["program"])
        put_rainbow()
        if script is not None:
            self.script.resume(*script)
        self.host.buttons = values["buttons"]
        put_program()

    def handle_events(self, events: list[HostEvent]) -> None:
        self.log.given(events)
        if self.script is not None and not self.script.finished:
            for e in self.script.due():
                self.machine.post(e)
                if self.on_input is not None and not self.log.rebuilding:
                    self.on_input(e)
            return  # the window's input counts once the script has played
        for ev in events:
            dev = self.host.convert(ev)
            if dev is not None:
                self.machine.post(dev)

    def tick(self) -> bool:
        alive = bool(self.step())
        self.log.ticked()
        ended = self.script is not None and self.end_with_script and self.script.finished
        return alive and not ended

    def frame(self) -> np.ndarray:
        return self.machine.shown()

    def time(self) -> Fraction:
        return Fraction(self.machine.frame_count, FPS)

    def wire(self) -> list[tuple[str, bytes]]:
        """The command stream since the last call (a machine made with ``record=True``)."""
        rec = self.machine.recording
        if rec is None:
            return []
        new = rec.entries[self._wire_at:]
        self._wire_at = len(rec.entries)
        out = [(d, data) for d, data in new if d in "><"]
        take_tape = getattr(self.tablet, "take_tape", None)  # a --tablet on tape (recording)
        if take_tape is not None:
            out.append(("T", take_tape()))
        return out


def target_schema(program: Any) -> Record:
    """A Rainbow program's whole declared state: the Rainbow (its own versioned state),
    the --events script's place, the window's mouse buttons and the program's own."""
    return Record(rainbow=Blob(), script=Opt(Tuple((Int(0), Int(0)))), buttons=Int(0, 7),
                  program=program)
