"""The harness target for a Sigma terminal on a paced serial line (``sigma run``): the line's
outside end is a bridge (pty, TCP, pyserial URL) to any program; an optional stream is
played down the line too.  One tick = 1/100 s of line time; 25 frames a second shown."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np

from emulator.host_input import HostEvent
from emulator.sigma.host_input import KEYS_HINT, to_terminal

TICK = Fraction(1, 100)  # virtual seconds per tick


class OutsideTap:
    """The line's host endpoint as a bridge sees it, keeping a copy of what comes from
    outside (the recording's ``+`` wire bytes, which a replay feeds back)."""

    def __init__(self, endpoint: Any) -> None:
        self._endpoint = endpoint
        self.taken = bytearray()

    def write(self, data: bytes) -> Any:
        self.taken += data
        return self._endpoint.write(data)

    def __getattr__(self, name: str) -> Any:
        return getattr(self._endpoint, name)


class SigmaLineTarget:
    """``term`` (emulator.sigma.Terminal) on ``line`` (protocols.link.SerialLine), whose
    host end ``bridge`` serves (None in a replay: the recorded outside bytes come back
    through ``put_wire``).  Runs until ``until`` seconds of line time (None: for ever)."""

    fps = 25

    def __init__(self, term: Any, line: Any, bridge: Any, title: str,
                 until: Fraction | None = None, report: Any = None) -> None:
        self.term, self.line, self.bridge = term, line, bridge
        self.title, self.keys = title, KEYS_HINT
        self.size = (768, 512)
        self.until = until
        self.report = report or (lambda kind, detail: None)
        self._sent = bytearray()
        self._received = b""
        self.tap = OutsideTap(line.host)  # give this to the bridge as its endpoint
        term.on_output = self._up

    def _up(self, data: bytes) -> None:
        self._sent += data
        self.line.device.write(data)

    def handle_events(self, events: list[HostEvent]) -> None:
        for ev in events:
            to_terminal(ev, self.term)

    def tick(self) -> bool:
        if self.bridge is not None:
            for ev in self.bridge.poll(timeout=0.0).events:
                if ev.kind in ("error", "disconnected", "refused"):
                    self.report(ev.kind, ev.detail)
        self._received = self.line.device.read()
        self.term.feed(self._received)
        self.line.clock.advance(TICK)
        return self.until is None or self.line.clock.exact < self.until

    def frame(self) -> np.ndarray:
        return self.term.frame()

    def time(self) -> Fraction:
        return self.line.clock.exact

    def wire(self) -> list[tuple[str, bytes]]:
        """This tick's traffic: bytes the terminal received, sent, and what came from outside."""
        sent, self._sent = bytes(self._sent), bytearray()
        outside, self.tap.taken = bytes(self.tap.taken), bytearray()
        return [("+", outside), (">", self._received), ("<", sent)]

    def put_wire(self, data: bytes) -> None:
        self.line.host.write(data)


class SigmaProgramTarget:
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
        """The program's bytes to the terminal since the last call."""
        sent = self.session.sent[getattr(self, "_sent_at", 0):]
        self._sent_at = len(self.session.sent)
        return [(">", b"".join(data for _t, data in sent))]


class PeriodTarget:
    """A terminal fed period by period by a program's generator (KAS's line test): each
    tick takes one period (``next(periods)`` feeds the terminal and yields its index); the
    generator's return value is kept in ``result``."""

    keys = "close the window to stop"

    def __init__(self, term: Any, periods: Any, fps: float, title: str) -> None:
        self.term, self.periods, self.title = term, periods, title
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
