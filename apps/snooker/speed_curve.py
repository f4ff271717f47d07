"""How a ball slows down: speed against time since it was last set moving (§6.1.2, fig 6.2).

The thesis's simulation used "a digitised version of the curve gained by observation".  The
figure itself is not legible in our copy of the thesis, so the curve below is OUR digitisation
of its written description:

* the very early part is the sliding part and has the shape of the theoretical curve
  V = k/(t + t0) -- we sample 1/(1 + u/0.1) for u in [0, 0.04];
* "when the ball starts to roll, the change of speed is more linear" -- a straight line
  from about 70 % of the initial speed down to about 15 %;
* "a final rapid down-turn in velocity just before the ball comes to rest" -- the last 12 %
  of the time drops from 15 % to 0.

The curve is normalised: u = time / T and g = speed / initial speed, where the time to rest
T = initial speed / `Table.deceleration_m_s2`, so a harder shot takes proportionally longer
to stop (and, like a real ball, travels a distance proportional to the square of its speed).
A collision with another ball or a change by the animator starts the ball on a fresh curve
from its new speed (a struck object ball does slide before rolling); a cushion scales the
curve by the change of speed, keeping the ball at the same point along it.

The simulation samples the curve only at frame boundaries: "velocity remains constant for
1/25 second, then suddenly drops to the value for the next frame" (§6.2).

Strategies are named after their source, as in pooltool; `Table.speed_curve` selects one.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from camlab88.apps.snooker.table import Table

# (u, g) pairs: our digitisation of fig 6.2's observed curve, described above.
PULLEN1987_OBSERVED: tuple[tuple[float, float], ...] = (
    (0.00, 1.000), (0.01, 0.909), (0.02, 0.833), (0.03, 0.769), (0.04, 0.714),  # sliding
    (0.06, 0.690), (0.20, 0.597), (0.40, 0.463), (0.60, 0.330), (0.80, 0.197),  # rolling
    (0.88, 0.150), (0.92, 0.110), (0.95, 0.065), (0.98, 0.022), (1.00, 0.000),  # down-turn
)
_U = np.array([p[0] for p in PULLEN1987_OBSERVED])
_G = np.array([p[1] for p in PULLEN1987_OBSERVED])

# Below this a ball on the theoretical (never-ending) curve is taken to have stopped.
SLIDING_STOP_SPEED_M_S = 0.005


def pullen1987_observed(v0: np.ndarray, tau: np.ndarray, table: Table) -> np.ndarray:
    """Speed at time `tau` after a ball was set moving at `v0` (arrays, m/s and s)."""
    v0 = np.asarray(v0, dtype=np.float64)
    tau = np.asarray(tau, dtype=np.float64)
    t_rest = v0 / table.deceleration_m_s2
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.where(t_rest > 0, tau / np.where(t_rest > 0, t_rest, 1.0), 1.0)
    return np.where(v0 > 0, v0 * np.interp(u, _U, _G, right=0.0), 0.0)


def pullen1987_sliding(v0: np.ndarray, tau: np.ndarray, table: Table) -> np.ndarray:
    """The theoretical sliding curve V = k/(t + t0) of §6.1.2; t0 (the time for the speed to
    halve) is a tenth of the observed curve's time to rest, matching its early part."""
    v0 = np.asarray(v0, dtype=np.float64)
    tau = np.asarray(tau, dtype=np.float64)
    t0 = 0.1 * v0 / table.deceleration_m_s2
    with np.errstate(divide="ignore", invalid="ignore"):
        v = np.where(v0 > 0, v0 * t0 / np.where(v0 > 0, tau + t0, 1.0), 0.0)
    return np.where(v < SLIDING_STOP_SPEED_M_S, 0.0, v)


SpeedCurve = Callable[[np.ndarray, np.ndarray, Table], np.ndarray]

CURVES: dict[str, SpeedCurve] = {
    "pullen1987-observed": pullen1987_observed,
    "pullen1987-sliding": pullen1987_sliding,
}


# Curves given as a normalised (u, g) table, which the compiled frame loop can evaluate.
CURVE_TABLES: dict[str, tuple[np.ndarray, np.ndarray]] = {"pullen1987-observed": (_U, _G)}


def curve_for(table: Table) -> SpeedCurve:
    try:
        return CURVES[table.speed_curve]
    except KeyError:
        raise ValueError(
            f"unknown speed curve {table.speed_curve!r}; known: {', '.join(CURVES)}"
        ) from None


def stopping_distance(v0: float, table: Table, start_offset: float = 0.0) -> float:
    """Distance a free ball set moving at `v0` travels before it stops, with the speed held
    for each frame as the simulation does (the first frame may be shortened by
    `start_offset`, the time since the last frame boundary)."""
    curve = curve_for(table)
    dt = table.frame_dt
    first = dt - start_offset
    taus = first + dt * np.arange(0, 100000)
    # Chunks keep this bounded for giant speeds without allocating huge arrays at once.
    dist = v0 * first
    for k in range(0, len(taus), 4096):
        v = curve(np.full(min(4096, len(taus) - k), v0), taus[k : k + 4096], table)
        zero = np.nonzero(v <= 0)[0]
        if len(zero):
            return float(dist + v[: zero[0]].sum() * dt)
        dist += v.sum() * dt
    return float(dist)
