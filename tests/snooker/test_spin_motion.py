"""Spin as a component along the main velocity while the ball runs (§6.1.2): top spin carries
it forward faster, back spin slows it, and back spin larger than the speed holds it still."""

from __future__ import annotations

import pytest

from camlab88.apps.snooker.physics import simulate_to_rest
from camlab88.apps.snooker.table import CUE, Table
from tests.snooker.helpers import state_with

T = Table()


def first_frame_step(spin: float) -> float:
    s = state_with(T, {CUE: (0.5, 0.9)}, {CUE: (1.0, 0.0)}, {CUE: spin})
    frames, _ = simulate_to_rest(T, s)
    return float(frames[1].pos[CUE, 0] - frames[0].pos[CUE, 0])


@pytest.mark.parametrize("spin", [0.3, -0.3])
def test_top_spin_runs_forward_back_spin_backward(spin) -> None:
    assert first_frame_step(spin) == pytest.approx((1.0 + spin) / T.frame_rate, rel=1e-12)


def test_back_spin_larger_than_the_speed_holds_the_ball_still() -> None:
    assert first_frame_step(-1.5) == 0.0
