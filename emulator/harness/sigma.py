"""Harness targets for programs on a Sigma: a program session over the line (KAS's editor
and path fronts) and a terminal fed period by period (KAS's line test).  The terminal on a
line served to outside programs (``sigma run``) is emulator.harness.sigma_line."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np

from emulator.harness.program_state import SavesState, load_object_state, object_state
from emulator.host_input import HostEvent
from emulator.machine.state_file import MachineStateError


class SigmaProgramTarget(SavesState):
    """A program session on a Sigma over the line (KAS's editor and path fronts): ``session``
    has ``step(mouse, keys)``, ``due(events, i)``, ``busy()``, ``clock`` and ``front``
    (protocols side, duck-typed).  Window keys named in ``key_names`` (or printable
    characters) are struck on the terminal; the left mouse button is the stylus tip.  A
    timed ``script`` (session events) plays first; with ``end_with_script`` the run ends once
    it has played and the screen has settled (at most ``settle_limit`` s more)."""

    fps = 25

    def __init__(self, session: Any, title: str, keys: str, key_names: frozenset[str],
                 script: list[Any], end_with_script: bool,
                 settle_limit: Fraction = Fraction(3600)) -> None:
        self.session, self.title, self.keys = session, title, keys
        self.size = (768, 512)
        self.key_names = key_names
        self.script, self.i = script, 0
        self.end_with_script = end_with_script
        self.settle_limit = settle_limit
        self._mouse: list[Any] = []
        self._keys: list[str] = []
        self._buttons = 0

    def handle_events(self, events: list[HostEvent]) -> None:
        from emulator.host_input import KeyDown, PointerButton, PointerMove
        from protocols.tablets.input_layer import MouseSample

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
            mouse, keys, self.i = self.session.due(self.script, self.i)
        self.session.step(mouse + self._mouse, keys + self._keys)
        self._mouse, self._keys = [], []
        if getattr(self.session.front, "quitting", False):
            return False  # the program was asked to quit (Esc) and may
        return not (self.end_with_script and self.settled())

    def settled(self) -> bool:
        """The script has played and the screen is up to date (the line quiet)."""
        if self.i < len(self.script):
            return False
        if self.session.busy() and self.time() > self._script_end() + self.settle_limit:
            raise ValueError(f"the session did not settle within {self.settle_limit} s of "
                             "line time")
        return not self.session.busy()

    def _script_end(self) -> Fraction:
        return self.script[-1].t if self.script else Fraction(0)

    def frame(self) -> np.ndarray:
        return self.session.terminal.frame()

    def time(self) -> Fraction:
        return self.session.clock.exact

    def may_close(self) -> bool:
        return bool(self.session.front.may_close())

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
    """A terminal fed period by period by a program's generator (KAS's line test): each
    tick takes one period (``next(periods)`` feeds the terminal and yields its index); the
    generator's return value is kept in ``result``.

    Its state: the period reached and the terminal. A generator cannot be saved, so loading
    one makes the program's generator again (``restart()``) and runs it to the saved period
    (deterministic, on virtual time); the terminal then takes the saved state."""

    keys = "close the window to stop"

    def __init__(self, term: Any, periods: Any, fps: float, title: str,
                 restart: Any = None) -> None:
        self.term, self.periods, self.title = term, periods, title
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
        return self.term.frame()

    def time(self) -> Fraction:
        return self.k / self._period

    def save_state(self) -> bytes:
        from emulator.machine.state_file import pack

        if self.result is not None:
            raise MachineStateError("the line test has finished: nothing left to save")
        return pack("period", {"k": self.k}, {"terminal": object_state(self.term)})

    def load_state(self, data: bytes) -> None:
        from emulator.machine.state_file import unpack

        head, blobs = unpack(data, "period")
        k = head.get("k")
        if type(k) is not int or k < 0 or "terminal" not in blobs:
            raise MachineStateError("line test state: the period or the terminal is missing")
        if k < self.k or self.result is not None:
            if self.restart is None:
                raise MachineStateError("this line test cannot go back")
            self.periods, self.k, self.result = self.restart(), 0, None
        while self.k < k:  # the program's generator run to the saved period
            if not self.tick():
                raise MachineStateError(f"the line test ends before period {k}")
        load_object_state(self.term, blobs["terminal"])
