"""What `--help` says runs without --speed is what runs: a program's window at period speed
and its headless run flat out; a replay flat out, in a window too, and `--period` at period
speed. The help is read from the command line itself; the speed from the harness's pacer
after a run (an injected clock and window: nothing sleeps, no display)."""

from __future__ import annotations

import pytest

from camlab88.cli import main
from camlab88.emulator.harness.control_options import Controls
from camlab88.emulator.harness.replay import Replay
from tests.controls.fakes import FakeClock, FakeWindow, harness_with
from tests.support.targets import Counter


def _speed_help(argv: list[str], capsys: pytest.CaptureFixture[str]) -> str:
    with pytest.raises(SystemExit):
        main([*argv, "--help"])
    text = " ".join(capsys.readouterr().out.split())
    return text[text.index("--speed X run at"):].split(" --video")[0]


def _speed_run(window: bool, replay: Replay | None = None) -> float | None:
    clock = FakeClock()
    h = harness_with(Counter(5), FakeWindow() if window else None, clock)
    if replay is not None:
        c = replay.controls or Controls()
        c.monotonic, c.sleep = clock.monotonic, clock.sleep
        replay.controls = c
        replay.adjust(h.options)
    h.run()
    return h.pacer.speed


@pytest.mark.parametrize("argv", [["rainbow", "run"], ["sigma", "render"], ["ca", "program"]])
def test_a_program_runs_at_the_speed_its_help_states(argv, capsys) -> None:
    said = _speed_help(argv, capsys)
    assert "default: a window at period speed, headless flat out" in said, said
    assert _speed_run(window=True) == 1.0
    assert _speed_run(window=False) is None


def test_a_replay_runs_at_the_speed_its_help_states(capsys) -> None:
    said = _speed_help(["replay"], capsys)
    assert "default: flat out, in a window too (--period is --speed 1)" in said, said
    assert _speed_run(window=True, replay=Replay(rec=None)) is None
    assert _speed_run(window=False, replay=Replay(rec=None)) is None
    assert _speed_run(window=True, replay=Replay(rec=None, period=True)) == 1.0
