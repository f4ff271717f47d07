"""A Sigma terminal on its serial line: the virtual clock, the paced line, the terminal and
the line's host end as the port a host program talks to. One object owns them all, ticks
them together and saves and restores all of them."""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction

import numpy as np

from camlab88.emulator.machine.state_file import MachineStateError, pack, unpack
from camlab88.emulator.protocol_trace import TraceEvent
from camlab88.emulator.sigma import Terminal
from camlab88.emulator.sigma.trace import SigmaTracer
from camlab88.protocols.link import LineSettings, SerialLine, VirtualClock
from camlab88.protocols.link.clock import TimeLike, to_time
from camlab88.protocols.link.line import Endpoint, RecorderLike
from camlab88.protocols.link.port import LinePort

TICK = Fraction(1, 100)  # how often the terminal takes what has arrived (as `sigma run`)


class HostPort(LinePort):
    """The host end of the line: what a host program writes and reads, on virtual time
    (protocols.link.port.LinePort)."""


class SigmaMachine:
    """Clock + line + terminal + host port (``host``), ticked together."""

    FPS = 25

    def __init__(self, model: str = "t5684", settings: LineSettings | None = None,
                 xonxoff: bool = True, recorder: RecorderLike | None = None) -> None:
        self.settings = settings or LineSettings()
        self.clock = VirtualClock()
        self.line = SerialLine(self.settings, self.clock, xonxoff, recorder)
        self.terminal = Terminal(model)
        self.terminal.on_output = self._up
        self.host = HostPort(self.line)
        self.tracer: SigmaTracer | None = None
        self._watch_sent: Callable[[bytes], None] | None = None

    def _up(self, data: bytes) -> None:
        self.line.device.write(data)
        if self._watch_sent is not None:
            self._watch_sent(data)

    def watch_sent(self, observer: Callable[[bytes], None] | None) -> None:
        """Tell ``observer`` every byte the terminal sends up the line (None: stop)."""
        self._watch_sent = observer

    # ------------------------------------------------------------------ time
    @property
    def now(self) -> Fraction:
        return self.clock.exact

    def tick(self, dt: TimeLike = TICK, take_first: bool = False) -> bytes:
        """Advance the clock by ``dt``; the terminal takes every byte that has arrived.
        ``take_first``: it takes them before the clock moves instead, so the screen after
        the tick is the line as it stood at the tick's start (the KAS programs' order,
        kept so their sessions show what they always showed).  Returns the bytes taken."""
        if take_first:
            taken = self.take()
            self.clock.advance(dt)
            return taken
        self.clock.advance(dt)
        return self.take()

    def take(self) -> bytes:
        """The terminal takes every byte that has arrived by now (returned)."""
        if self.tracer is None:
            data = self.line.device.read()
            if data:
                self.terminal.feed(data)
            return data
        step = self.settings.char_time
        runs = self.line.device.read_timed(exact=True)
        for t_last, data in runs:
            first = t_last - (len(data) - 1) * step
            self.tracer.feed(data, float(first), float(step))
        return b"".join(data for _t, data in runs)

    def run_until(self, t: TimeLike, tick: TimeLike = TICK) -> None:
        """Tick (at most ``tick`` at a time) until the clock reads ``t``."""
        end, step = to_time(t), to_time(tick)
        while self.clock.exact < end:
            self.tick(min(step, end - self.clock.exact))

    def idle_time(self) -> Fraction:
        """When both directions will have delivered everything queued (a direction held
        by XOFF for ever is left out)."""
        ends = [self.line.host.drain_time_exact(), self.line.device.drain_time_exact()]
        finite = [Fraction(e) for e in ends if e != float("inf")]
        return max([self.clock.exact, *finite])

    def frame(self) -> np.ndarray:
        """(512, 768, 3) uint8 as displayed, row 0 = top."""
        return self.terminal.frame()

    def indices(self) -> np.ndarray:
        """(512, 768) uint8 LUT indices on the screen, row 0 = top."""
        return np.ascontiguousarray(self.terminal.indices()[::-1])

    # ------------------------------------------------------------------ the outside end
    @property
    def outside(self) -> Endpoint:
        """The line's host end as an outside program's bridge serves it (a pty, a TCP
        client, a serial port): bytes written go down the line, ``hang_up`` ends a client."""
        return self.line.host

    def drop_partial_order(self, why: str) -> None:
        """Forget the order the terminal has half received (its sender hung up: ``why``):
        the next sender starts on an order boundary. The half order is counted and traced
        as malformed, as a next sender's bytes cutting it short would be."""
        decoder = self.terminal.decoder
        try:
            if decoder.mid_order:
                decoder.stats.malformed += 1
                if self.tracer is not None:
                    self.tracer.cut_short(float(self.clock.exact), why)
        finally:
            decoder.drop_partial()

    def busy(self) -> bool:
        """Bytes are on their way along the line, either direction."""
        return bool(self.line.host.has_in_flight() or self.line.device.has_in_flight())

    def reading_cursor(self) -> bool:
        """A cursor read is armed (HF): the next key or stylus press reports the crosshair."""
        return bool(self.terminal.reg.cursor_report)

    def finish(self) -> None:
        """Let the line deliver everything queued (a line recording's end)."""
        self.line.finish()

    @property
    def stats(self) -> dict[str, int]:
        """The terminal's counts: bytes, commands, unknown, malformed, errors."""
        return self.terminal.stats

    @property
    def line_stats(self) -> dict[str, int]:
        """The line's counts (``host_to_device_bytes`` ...)."""
        return self.line.stats

    def in_flight(self) -> bool:
        """Bytes from the terminal are still on their way up the line."""
        return bool(self.line.device.in_flight())

    def orders(self) -> tuple[int, bool]:
        """(orders the terminal has completed, whether one is half received now)."""
        decoder = self.terminal.decoder
        return decoder.stats.commands, bool(decoder.mid_order)

    # ------------------------------------------------------------------ the user
    def key(self, char: str) -> None:
        """A character typed on the terminal's keyboard (ends a cursor read, else goes up
        the line)."""
        self.terminal.key(char)

    def cursor(self, x: int, y: int) -> None:
        """Move the crosshair with the joystick to drawing-area (x, y) (device units, y up;
        a crosshair on the tablet does not move)."""
        reg = self.terminal.reg
        self.terminal.cursor_keys(x - reg.cursor_x, y - reg.cursor_y)

    def tablet(self, x: int, y: int, pressed: bool) -> None:
        """The stylus at screen (x, y) (device units, y up); a press ends a cursor read."""
        self.terminal.tablet(x, y, pressed)

    def press(self, name: str, shift: bool = False) -> None:
        """A key struck on the terminal's keyboard (by its user, not the host), named as in
        protocols.sigma.keyboard or a printable character: what it sends goes up the line
        now (a cursor key during a cursor read moves the crosshair instead)."""
        self.terminal.press(name, shift)

    # ------------------------------------------------------------------ traces
    def trace(self, sink: Callable[[TraceEvent], None] | None,
              strict: bool = False) -> SigmaTracer | None:
        """Report every decoded order to ``sink`` from now on (None: stop tracing);
        ``strict`` raises ProtocolError at the first unknown, malformed or out-of-range one."""
        if sink is None:
            self.tracer = None
            return None
        self.tracer = SigmaTracer(self.terminal, sink, strict)
        self.tracer.offset = self.tracer.start = self.terminal.decoder.stats.bytes_in
        return self.tracer

    # ------------------------------------------------------------------ state
    def save_state(self) -> bytes:
        """Clock, line (queued bytes, UART ticks, flow control) and terminal, versioned."""
        header = {"model": self.terminal.model.name, "settings": str(self.settings),
                  "xonxoff": self.line.xonxoff, "clock": self.clock.save_state(),
                  "line": self.line.save_state()}
        return pack("sigma", header, {"terminal": self.terminal.save_state()})

    def load_state(self, data: bytes) -> None:
        """Continue from save_state()'s bytes; MachineStateError if they do not fit (and
        then nothing has changed)."""
        head, blobs = self.check_state(data)
        self.line.load_state(head["line"])
        self.terminal.load_state(blobs["terminal"])
        self.clock.load_state(head["clock"])
        if self.tracer is not None:
            self.trace(self.tracer.sink, self.tracer.strict)

    def check_state(self, data: bytes) -> tuple[dict, dict[str, bytes]]:
        """MachineStateError unless ``data`` loads into this machine (every part is tried
        on a scratch copy; this machine is not touched); its header and parts."""
        head, blobs = unpack(data, "sigma")
        for key, mine in (("model", self.terminal.model.name),
                          ("settings", str(self.settings)), ("xonxoff", self.line.xonxoff)):
            if head.get(key) != mine:
                raise MachineStateError(f"machine state has {key} {head.get(key)!r}, this "
                                        f"machine {mine!r}")
        fresh = Terminal(self.terminal.model.name)
        try:  # check every part on scratch copies before anything changes
            VirtualClock().load_state(head.get("clock"))
            fresh.load_state(blobs.get("terminal", b""))
            SerialLine(self.settings, VirtualClock(), self.line.xonxoff).load_state(head["line"])
        except (ValueError, KeyError) as exc:
            raise MachineStateError(f"machine state: {exc}") from None
        return head, blobs
