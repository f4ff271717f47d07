"""--speed: the frame limiter paces the wall clock to virtual time exactly (an injected
clock: no real sleeping)."""

from __future__ import annotations

import pytest

from camlab88.emulator.harness.pace import Pacer
from tests.controls.fakes import FakeClock, harness_with
from tests.support.targets import Counter


@pytest.mark.parametrize("speed, wall", [(1.0, 1.98), (10.0, 0.198), (0.5, 3.96)])
def test_a_paced_run_takes_its_virtual_time_over_the_speed(speed, wall) -> None:
    clock = FakeClock()
    start = clock.now
    h = harness_with(Counter(101), None, clock, speed=speed).run()  # 100 ticks of 1/50 s
    assert float(h.target.time()) == 2.02
    # paced after ticks 1..100 (the last tick ends the run): t = 0.02 anchors, 2.00 ends
    assert clock.now - start == pytest.approx(wall)


def test_headless_without_speed_runs_flat_out() -> None:
    clock = FakeClock()
    harness_with(Counter(50), None, clock).run()
    assert clock.slept == []


def test_a_late_run_catches_up_but_a_change_of_speed_re_anchors() -> None:
    clock = FakeClock()
    p = Pacer(1.0, clock.monotonic, clock.sleep)
    p.pace(0)
    clock.now += 0.5          # a slow tick: half a second late at t = 0.1
    p.pace(0.1)
    assert clock.slept == []  # no sleep while behind ...
    p.pace(0.7)
    assert clock.slept == [pytest.approx(0.2)]  # ... and the lost time is made up
    p.set_speed(2.0, 0.7)
    p.pace(1.7)
    assert clock.slept[-1] == pytest.approx(0.5)  # one virtual second at double speed


def test_flat_out_reports_the_speed_it_achieved() -> None:
    clock = FakeClock()
    p = Pacer(None, clock.monotonic, clock.sleep)
    p.pace(0)
    clock.now += 0.25
    p.pace(1)
    assert p.achieved(1) == pytest.approx(4.0) and clock.slept == []


def test_speed_must_be_positive() -> None:
    with pytest.raises(ValueError, match="positive"):
        Pacer(0.0, FakeClock().monotonic, FakeClock().sleep)


def test_a_replay_takes_its_own_controls_and_period_is_speed_one() -> None:
    from camlab88.emulator.harness import RunOptions
    from camlab88.emulator.harness.control_options import Controls
    from camlab88.emulator.harness.replay import Replay

    recorded = RunOptions(controls=Controls(speed=50.0))  # what the recorded command asked
    Replay(rec=None, period=True).adjust(recorded)
    assert recorded.controls.speed == 1.0
    mine = Controls(speed=10.0)
    Replay(rec=None, controls=mine).adjust(recorded)
    assert recorded.controls is mine
    Replay(rec=None).adjust(recorded)
    assert recorded.controls.speed is None  # flat out, as a replay always was
