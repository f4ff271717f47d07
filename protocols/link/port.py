"""The port a host program talks to: its end of the line to a device.

Host programs (apps/) are typed against this and nothing else: they write bytes, read what
came back, ask the line's time and whether everything written has been taken.  Who runs the
line and the device -- the machine, ticked by a command or the harness -- is not their
business (emulator.machine.SigmaMachine.host satisfies it).
"""

from __future__ import annotations

from fractions import Fraction
from typing import TYPE_CHECKING, Protocol

import numpy as np

if TYPE_CHECKING:
    from camlab88.protocols.link.line import SerialLine


class HostPort(Protocol):
    """A host program's end of a line to a device, on the line's (virtual) time."""

    def write(self, data: bytes) -> float:
        """Queue bytes now; returns the line time the last one reaches the device."""
        ...

    def read(self) -> bytes:
        """Bytes the device sent that have arrived by now (consumed)."""
        ...

    @property
    def now(self) -> float:
        """The line's time in seconds."""
        ...

    @property
    def exact(self) -> Fraction:
        """The line's time as an exact Fraction (for programs that schedule by it)."""
        ...

    def drained(self) -> bool:
        """Everything written so far has arrived at the device and been taken by it."""
        ...

    def drain_exact(self) -> Fraction:
        """The exact line time everything written so far will have arrived (for programs
        that schedule by it)."""
        ...


class LinePort:
    """The host end of a SerialLine as a HostPort (what a machine hands its host program)."""

    def __init__(self, line: SerialLine) -> None:
        self._line = line

    def write(self, data: bytes) -> float:
        return self._line.host.write(bytes(data))

    def read(self) -> bytes:
        return self._line.host.read()

    @property
    def now(self) -> float:
        return self._line.clock.now

    @property
    def exact(self) -> Fraction:
        return self._line.clock.exact

    def drained(self) -> bool:
        host = self._line.host
        return host.drain_time() <= self._line.clock.now and host.in_flight() == 0

    def drain_exact(self) -> Fraction:
        return Fraction(self._line.host.drain_time_exact())


class BatchLink(Protocol):
    """What a batch host program (a renderer, an exporter) is handed by whoever runs its
    machine: the ``port``, ``wait()`` -- block until everything written has arrived and been
    taken, as a host process blocks in tcdrain() while the line runs -- and the screen, to
    keep (``frame``: RGB, row 0 = top) and to measure (``indices``: LUT indices, row 0 =
    top)."""

    @property
    def port(self) -> HostPort: ...

    def wait(self) -> None: ...

    def frame(self) -> np.ndarray: ...

    def indices(self) -> np.ndarray: ...
