"""The harness target for a program on a Rainbow machine (snooker, CA, the Rainbow demo,
and new Rainbow programs).  One tick = one program step, normally one 1/50 s display frame.
"""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction
from typing import Any

import numpy as np

from camlab88.base.plainstate import Blob, Int, Opt, Record, Tuple
from camlab88.emulator.host_input import HostEvent
from camlab88.emulator.machine import RainbowMachine
from camlab88.emulator.machine.state_file import MachineStateError
from camlab88.emulator.rainbow.host_input import RainbowHostInput
from camlab88.protocols.rainbow.script import Player

FPS = 50  # the Rainbow's display frames per second


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
        if program is not None:  # it declares its state: so does the target
            self.program = program
            self.STATE_VERSION = program.STATE_VERSION
            self.STATE_SCHEMA = target_schema(program.STATE_SCHEMA)

    # ------------------------------------------------------------------ declared state
    def state_values(self) -> dict[str, Any]:
        """The Rainbow and its client (RainbowMachine.session_state), the script's place,
        the window's mouse buttons and the program's own declared state."""
        script = None if self.script is None else (
            self.script.played(), self.script.wait)
        return {"rainbow": self.machine.session_state(), "script": script,
                "buttons": self.host.buttons, "program": self.program.state_values()}

    def load_state_values(self, values: dict[str, Any]) -> None:
        """Continue from state_values() (checked against STATE_SCHEMA): every part is
        checked before anything changes."""
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
        if self.script is not None and not self.script.finished:
            for e in self.script.due():
                self.machine.post(e)
                if self.on_input is not None:
                    self.on_input(e)
            return  # the window's input counts once the script has played
        for ev in events:
            dev = self.host.convert(ev)
            if dev is not None:
                self.machine.post(dev)

    def tick(self) -> bool:
        alive = bool(self.step())
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
