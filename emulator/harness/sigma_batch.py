"""Running a Sigma machine for a batch command (render, export, the demo's pictures): no
window and no input, only the line's time moving until what was written has arrived.  The
interactive runs tick a machine in the harness loop (emulator.harness.sigma)."""

from __future__ import annotations

from collections.abc import Generator, Iterator
from typing import Any

import numpy as np

from camlab88.emulator.machine import HostPort, SigmaMachine
from camlab88.protocols.link import LineSettings
from camlab88.protocols.link.clock import TimeLike, to_time


def settle(machine: SigmaMachine) -> None:
    """Run until everything queued on the line has arrived and been taken, in one step of
    line time (however far off the last byte is: a recording may say hours)."""
    machine.tick(machine.idle_time() - machine.now)


def periods(machine: SigmaMachine, period: TimeLike,
            start: TimeLike = 0) -> Iterator[int]:
    """Period by period of line time from ``start``: yields k once the machine has run to
    the end of period k, while what was written is still on its way (the caller may write
    more between periods).  The screen after period k shows every byte arrived by then."""
    p, t0 = to_time(period), to_time(start)
    k = 0
    while not machine.host.drained():
        machine.run_until(t0 + (k + 1) * p)
        yield k
        k += 1


def still(data: bytes, model: str = "t5684") -> SigmaMachine:
    """A fresh terminal that has taken ``data`` over its line (no flow control)."""
    machine = SigmaMachine(model, xonxoff=False)
    machine.host.write(data)
    settle(machine)
    return machine




class MachineLink:
    """A machine handed to a batch host program (protocols.link.port.BatchLink): its port,
    and ``wait`` runs the machine until the line is quiet."""

    def __init__(self, machine: SigmaMachine) -> None:
        self.machine = machine

    @property
    def port(self) -> HostPort:
        return self.machine.host

    def wait(self) -> None:
        settle(self.machine)

    def frame(self) -> np.ndarray:
        return self.machine.frame()

    def indices(self) -> np.ndarray:
        return self.machine.indices()


def link(model: str = "t5684", baud: int = 9600, xonxoff: bool = True) -> MachineLink:
    """A fresh terminal on its line, handed over as a link."""
    return MachineLink(SigmaMachine(model, LineSettings(baud=baud), xonxoff))


def t5688_link() -> MachineLink:
    """A fresh T5688 on a 9600-baud line (picklable by name, for render workers)."""
    return link("t5688")


def host_periods(machine: SigmaMachine, host: Any, period: TimeLike) -> Generator[int, None, Any]:
    """A host program that acts at line times of its choosing (``host.wake``, None once it
    is done; ``host.act()``) on a machine shown period by period: the machine runs to each
    wake time in the period and the host acts, then to the period's end, and k is yielded;
    it ends when the host is done and every byte has arrived; returns ``host.finish()``."""
    p = to_time(period)
    k = 0
    while True:
        boundary = (k + 1) * p
        if host.wake is not None and host.wake <= boundary:
            machine.run_until(max(host.wake, machine.now))
            host.act()
            continue
        if host.wake is None and k * p >= machine.host.drain_exact():
            break
        machine.run_until(boundary)
        yield k
        k += 1
    return host.finish()
