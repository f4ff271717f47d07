"""Ctrl-C (or SIGTERM) while a harness runs takes effect between two ticks, never inside one
(emulator/harness/signals.py): a recording made up to a Ctrl-C ends at a tick a replay
reaches, with that tick's frame shown ("expected the end at frame 249, tick 997, got the end
at frame 250" was a Ctrl-C landing between a tick's clock step and its frame)."""

from __future__ import annotations

import os
import signal
from fractions import Fraction
from pathlib import Path

import pytest

from camlab88.emulator.harness import RunOptions, run
from camlab88.emulator.harness.sigma_line import TICK, SigmaLineTarget
from camlab88.emulator.machine import SigmaMachine
from camlab88.protocols.session import read


class _InterruptedMidTick(SigmaLineTarget):
    """Sends itself a signal in the middle of tick ``at``: after the line time advanced,
    before the harness could count the tick or show its frame."""

    def __init__(self, at: int, signum: int) -> None:
        super().__init__(SigmaMachine("t5684"), None, "test")
        self.at, self.signum, self.n = at, signum, 0
        self.machine.outside.write(b"\r+-*/HI2GI200200GJ600200600400200400200200")

    def tick(self) -> bool:
        alive = super().tick()
        self.n += 1
        if self.n == self.at:
            os.kill(os.getpid(), self.signum)
        return alive


@pytest.mark.parametrize("at", [37, 38, 40, 41])
def test_a_ctrl_c_mid_tick_ends_the_recording_on_that_ticks_boundary(tmp_path: Path,
                                                                      at: int) -> None:
    rec = tmp_path / "s.session"
    target = _InterruptedMidTick(at, signal.SIGINT)
    with pytest.raises(KeyboardInterrupt):
        run(target, RunOptions(headless=True, paced=False, record=rec,
                               argv=["sigma", "run", "--headless"]))
    end = read(rec).end
    assert end is not None and end.tick == at  # the tick in progress completed
    assert end.time == at * TICK == target.time()
    assert end.frame == (at + 3) // 4  # frames at ticks 1, 5, 9, ...: as a replay shows them


def test_sigterm_is_delivered_after_the_tick_too(tmp_path: Path) -> None:
    caught: list[int] = []

    def terminate(signum: int, frame: object) -> None:
        caught.append(signum)
        raise SystemExit(143)

    old = signal.signal(signal.SIGTERM, terminate)
    try:
        target = _InterruptedMidTick(21, signal.SIGTERM)
        with pytest.raises(SystemExit):
            run(target, RunOptions(headless=True, paced=False, record=tmp_path / "t.session",
                                   argv=["sigma", "run", "--headless"]))
    finally:
        signal.signal(signal.SIGTERM, old)
    assert caught == [signal.SIGTERM]
    assert read(tmp_path / "t.session").end.tick == 21
    assert target.time() == Fraction(21, 100)
