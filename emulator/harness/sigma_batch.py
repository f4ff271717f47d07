"""Running a Sigma machine for a batch command (render, export, the demo's pictures): no
window and no input, only the line's time moving until what was written has arrived.  The
interactive runs tick a machine in the harness loop (emulator.harness.sigma)."""

from __future__ import annotations

from collections.abc import Iterator

from emulator.machine import SigmaMachine
from protocols.link.clock import TimeLike, to_time


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


