"""A line with nobody at its far end, for a host program's timing alone: what it would send
and when (the KAS viewer's report, the demo's host bytes).  No device is fed; the line owns
its clock: ``run_to`` moves it on, ``take`` hands back what has arrived at the far end."""

from __future__ import annotations

from fractions import Fraction

from camlab88.protocols.link.clock import TimeLike, VirtualClock, to_time
from camlab88.protocols.link.line import SerialLine
from camlab88.protocols.link.port import LinePort
from camlab88.protocols.link.settings import LineSettings


class HostOnlyLine:
    """``port`` for the host; the far end only counts what arrives."""

    def __init__(self, settings: LineSettings | None = None) -> None:
        self._line = SerialLine(settings or LineSettings(), VirtualClock())
        self.port = LinePort(self._line)

    @property
    def now(self) -> Fraction:
        return self._line.clock.exact

    def run_to(self, t: TimeLike) -> None:
        """Move the clock on to ``t`` (never back)."""
        self._line.clock.advance_to(max(to_time(t), self._line.clock.exact))

    def take(self) -> bytes:
        """The bytes that have arrived at the far end by now (counted, dropped)."""
        return self._line.device.read()

    def in_flight(self) -> int:
        """Bytes written that have not yet arrived and been counted."""
        return self._line.host.in_flight()
