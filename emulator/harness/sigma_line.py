"""The harness target for a Sigma terminal on a paced serial line (``sigma run``): the line's
outside end is a bridge (pty, TCP, pyserial URL) to any program; an optional stream is
played down the line too.  One tick = 1/100 s of line time; 25 frames a second shown.

What comes from outside is recorded at the tick it entered the line (``+`` bytes, ``-`` the
line hanging up between clients), and a replay applies it at the same point of the same tick,
where the bridge would have been polled, so a session fed by an outside program replays
exactly.  A client that leaves half an order unfinished for ``order_timeout`` seconds of line
time is hung up on; when the line hangs up, the half order goes with it (the next client
starts on an order boundary; the screen, modes and registers stay, as on a terminal whose
cable is swapped).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np

from camlab88.base.plainstate import Blob, Bool, Frac, Int, Opt, Record
from camlab88.emulator.host_input import HostEvent
from camlab88.emulator.machine import SigmaMachine
from camlab88.emulator.machine.state_file import MachineStateError
from camlab88.emulator.sigma.host_input import KEYS_HINT, to_terminal

TICK = Fraction(1, 100)  # virtual seconds per tick
ORDER_TIMEOUT = Fraction(10)  # s of line time a half-received order may wait for its rest


class OutsideTap:
    """The line's host endpoint as a bridge sees it, keeping what came from outside during
    the current tick, in order: ``("+", bytes)`` that entered the line and ``("-", b"")``
    when the line hung up between clients.  Only one tick's worth is ever kept (the target
    forgets it at the next tick): what is not recorded is not kept."""

    def __init__(self, endpoint: Any, on_hang_up: Any = None) -> None:
        self._endpoint = endpoint
        self._on_hang_up = on_hang_up
        self.taken: list[tuple[str, bytes]] = []

    def write(self, data: bytes) -> Any:
        self.taken.append(("+", bytes(data)))
        return self._endpoint.write(data)

    def hang_up(self) -> int:
        self.taken.append(("-", b""))
        dropped = int(self._endpoint.hang_up())
        if self._on_hang_up is not None:
            self._on_hang_up()
        return dropped

    def take(self) -> list[tuple[str, bytes]]:
        taken, self.taken = self.taken, []
        return taken

    def __getattr__(self, name: str) -> Any:
        return getattr(self._endpoint, name)


class SigmaLineTarget:
    """A Sigma machine whose line's host end ``bridge`` serves (None in a replay: the
    recorded outside traffic comes back through ``put_wire`` / ``put_hang_up``).  Runs until
    ``until`` seconds of line time (None: for ever).  Set the machine's tracer
    (``machine.trace``) for ``--trace`` / ``--strict``."""

    # its declared state (emulator.harness.program_state): the machine's own versioned
    # state, when the order now unfinished began, how many orders the terminal had done, the
    # --events script's place, when outside bytes last came and whether a client has left;
    # the bridge, the report and the until are the command line's, never a state's
    STATE_VERSION = 1
    STATE_SCHEMA = Record(machine=Blob(), order_since=Opt(Frac()), commands=Int(0),
                          script_at=Int(0), heard_at=Frac(), client_left=Bool())

    fps = 25
    escape_is_a_key = True  # a terminal key: host programs read ESC (close the window quits)

    def __init__(self, machine: SigmaMachine, bridge: Any, title: str,
                 until: Fraction | None = None, report: Any = None,
                 order_timeout: Fraction = ORDER_TIMEOUT,
                 until_idle: Fraction | None = None, script: list[Any] | None = None) -> None:
        self.machine, self.bridge = machine, bridge
        self.title, self.keys = title, KEYS_HINT
        self.size = (768, 512)
        self.until = until
        self.report = report or (lambda kind, detail: None)
        self.order_timeout = order_timeout
        self.until_idle = until_idle  # end once nothing came from outside for this long
        self.script = list(script or [])  # --events (protocols.sigma.input_script)
        self._script_at = 0  # the next script event
        self._heard_at = Fraction(0)  # line time outside bytes last came (or the line moved)
        self._sent = bytearray()
        self._received = b""
        self._frame: np.ndarray | None = None  # the picture, until the terminal changes
        self._replayed: list[tuple[str, bytes]] = []  # a replay's outside traffic, this tick
        self._order_since: Fraction | None = None  # when the unfinished order began
        self._commands = 0
        self._client_left = False  # a client went; its bytes may still be on the line
        self.tap = OutsideTap(machine.outside, self._line_hung_up)  # the bridge's endpoint
        machine.watch_sent(self._up)

    def state_values(self) -> dict[str, Any]:
        return {"machine": self.machine.save_state(), "order_since": self._order_since,
                "commands": self._commands, "script_at": self._script_at,
                "heard_at": self._heard_at, "client_left": self._client_left}

    def load_state_values(self, values: dict[str, Any]) -> None:
        """Continue from state_values() (checked against STATE_SCHEMA); the machine's part
        is checked whole before anything changes."""
        self.machine.check_state(values["machine"])
        if values["script_at"] > len(self.script):
            raise MachineStateError(f"the state is at --events script event "
                                    f"{values['script_at']}; this run's script has "
                                    f"{len(self.script)}")
        try:
            self.machine.load_state(values["machine"])
        except ValueError as exc:  # (checked above: not expected)
            raise MachineStateError(str(exc)) from None
        self._order_since, self._commands = values["order_since"], values["commands"]
        self._script_at, self._heard_at = values["script_at"], values["heard_at"]
        self._client_left = values["client_left"]
        self._frame, self._replayed, self._sent, self._received = None, [], bytearray(), b""
        self.tap.take()

    def _up(self, data: bytes) -> None:
        self._sent += data

    def handle_events(self, events: list[HostEvent]) -> None:
        # A new tick: an earlier tick's traffic nobody recorded is forgotten (memory bounded)
        self.tap.take()
        self._sent.clear()
        if events:
            self._frame = None
        for ev in events:
            to_terminal(ev, self.machine)

    def tick(self) -> bool:
        self._play_script()
        self._outside()
        # the terminal takes what has arrived by the tick's start, then the line moves on
        self._received = self.machine.tick(TICK, take_first=True)
        if self._received:
            self._frame = None
        self._watch_order(self.machine.now - TICK)
        self._left_half_order()
        return self._going()

    def _play_script(self) -> None:
        """The --events script's user acts: each event at its moment, in file order."""
        while self._script_at < len(self.script):
            ev = self.script[self._script_at]
            if ev.when == "at" and self.machine.now < Fraction(ev.at):
                return
            if ev.when == "reply" and not (self.machine.reading_cursor()
                                            and not self.machine.outside.has_in_flight()):
                return
            self._script_at += 1
            self._frame = None
            if ev.action == "key":
                for char in ev.text:
                    self.machine.key(char)
            elif ev.action == "cursor":
                self.machine.cursor(ev.x, ev.y)
            else:
                self.machine.tablet(ev.x, ev.y, ev.down)

    def script_done(self) -> bool:
        return self._script_at >= len(self.script)

    def _going(self) -> bool:
        now = self.machine.now
        if self.until is not None and now >= self.until:
            return False
        if any(d == "+" for d, _ in self.tap.taken) or self._received or self.busy():
            self._heard_at = now
        if not self.script_done():  # a script still to play keeps the run going
            return True
        return self.until_idle is None or now - self._heard_at < self.until_idle

    def _outside(self) -> None:
        """The outside end's turn: the bridge polled, or a replay's recorded traffic."""
        for d, data in self._replayed:
            if d == "+":
                self.machine.outside.write(data)
                self._heard_at = self.machine.now
            else:
                self.machine.outside.hang_up()
                self._line_hung_up()
        self._replayed = []
        if self.bridge is None:
            return
        if self._order_overdue():
            disconnect = getattr(self.bridge, "disconnect", None)  # a pty has no client
            if disconnect is not None:
                disconnect(f"half an order unfinished for {float(self.order_timeout):g} s "
                           "of line time")
        for ev in self.bridge.poll(timeout=0.0).events:
            if ev.kind in ("error", "disconnected", "refused") or (
                    ev.kind == "connected" and ev.detail.endswith(" is back")):
                self.report(ev.kind, ev.detail)
            if ev.kind in ("connected", "disconnected"):
                self._client_left = ev.kind == "disconnected"

    def _left_half_order(self) -> None:
        """A client that left half an order: once its last bytes have arrived, the line
        hangs up (recorded, so a replay does the same), which reports the half order."""
        if not self._client_left or self.machine.outside.has_in_flight():
            return
        self._client_left = False
        if self.machine.orders()[1]:
            self.tap.hang_up()

    def _watch_order(self, now: Fraction) -> None:
        """Note when the order now unfinished at the terminal began (``now``, this tick's
        start, if an order was completed or none was pending)."""
        commands, mid_order = self.machine.orders()
        done, self._commands = self._commands != commands, commands
        if not mid_order:
            self._order_since = None
        elif self._order_since is None or done:
            self._order_since = now

    def _order_overdue(self) -> bool:
        since = self._order_since
        return since is not None and self.machine.now - since >= self.order_timeout

    def _line_hung_up(self) -> None:
        """A client's half order leaves with it: the next client starts on an order boundary.
        It is counted and reported as malformed, as the bytes of a next client cutting it
        short would be over a pty (and ``--strict`` stops on it)."""
        try:
            self.machine.drop_partial_order("the client hanging up")
        finally:
            self._order_since = None

    def busy(self) -> bool:
        """Bytes are on their way along the line, either direction (the harness does not
        pace a live line then: it runs as fast as the outside end writes)."""
        return self.machine.busy()

    def frame(self) -> np.ndarray:
        """The terminal's picture; composed again only after bytes or input changed it (the
        terminal changes no other way), so an idle line costs no drawing."""
        if self._frame is None:
            self._frame = self.machine.frame()
        return self._frame

    def time(self) -> Fraction:
        return self.machine.now

    def wire(self) -> list[tuple[str, bytes]]:
        """This tick's traffic: what came from outside (``+`` bytes, ``-`` the line hanging
        up, in order), then the bytes the terminal received and sent."""
        sent, self._sent = bytes(self._sent), bytearray()
        return [*self.tap.take(), (">", self._received), ("<", sent)]

    def put_wire(self, data: bytes) -> None:
        """A replay: recorded outside bytes, put on the line where the bridge would be polled."""
        self._replayed.append(("+", data))

    def put_hang_up(self) -> None:
        """A replay: the line hung up here in the recorded run, so it hangs up again."""
        self._replayed.append(("-", b""))
