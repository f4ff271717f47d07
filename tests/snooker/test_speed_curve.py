"""The speed curve's shape (§6.1.2, fig 6.2): a sliding start like k/(t + t0), a linear part
while rolling, a rapid down-turn before rest; and the theoretical curve V = k/(t + t0)."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.snooker.speed_curve import (
    PULLEN1987_OBSERVED,
    pullen1987_observed,
    pullen1987_sliding,
)
from camlab88.apps.snooker.table import Table

T = Table()


def test_observed_curve_slides_like_k_over_t_plus_t0_then_rolls_linearly_then_turns_down()\
        -> None:
    u = np.array([p[0] for p in PULLEN1987_OBSERVED])
    g = np.array([p[1] for p in PULLEN1987_OBSERVED])
    sliding = u <= 0.04
    assert np.allclose(g[sliding], 1 / (1 + u[sliding] / 0.1), atol=1e-3)
    rolling = (u >= 0.06) & (u <= 0.80)
    slopes = np.diff(g[rolling]) / np.diff(u[rolling])
    assert np.allclose(slopes, slopes[0], rtol=0.02)  # a straight line
    turn = u >= 0.88
    turn_slopes = np.diff(g[turn]) / np.diff(u[turn])
    assert (turn_slopes < 1.5 * slopes[0]).all()  # steeper than rolling: the down-turn
    slide_slope = (g[1] - g[0]) / (u[1] - u[0])
    assert slide_slope < 4 * slopes[0]  # the sliding start is steeper still
    assert g[0] == 1.0 and g[-1] == 0.0 and (np.diff(g) < 0).all()


def test_observed_curve_is_scaled_by_the_time_to_rest() -> None:
    v0 = np.array([1.0, 2.0])
    t_rest = v0 / T.deceleration_m_s2
    half = pullen1987_observed(v0, 0.4 * t_rest, T)
    assert half == pytest.approx(0.463 * v0)
    assert (pullen1987_observed(v0, t_rest * 1.001, T) == 0).all()


def test_theoretical_curve_is_k_over_t_plus_t0() -> None:
    v0 = np.full(5, 2.0)
    t0 = 0.1 * 2.0 / T.deceleration_m_s2
    tau = np.array([0.0, 0.1, 0.5, 1.0, 3.0])
    assert pullen1987_sliding(v0, tau, T) == pytest.approx(2.0 * t0 / (tau + t0))
