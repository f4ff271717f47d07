"""Small builders shared by the snooker tests."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.state import BallState
from camlab88.apps.snooker.table import N_BALLS, Table


def state_with(table: Table, balls: dict[int, tuple[float, float]],
               vel: dict[int, tuple[float, float]] | None = None,
               spin: dict[int, float] | None = None) -> BallState:
    """Only the listed balls on the table; the rest potted (parked behind a pocket)."""
    pos = np.zeros((N_BALLS, 2))
    on = np.zeros(N_BALLS, dtype=bool)
    pos[:] = table.pockets[0].drop
    for i, p in balls.items():
        pos[i] = p
        on[i] = True
    m = BallState.at_rest(pos, on).thaw()
    for i, v in (vel or {}).items():
        m.set_velocity(i, v[0], v[1], (spin or {}).get(i, 0.0))
    return m.freeze()


def overlaps(table: Table, s: BallState, tol: float = 1e-9) -> float:
    """Smallest gap between two on-table balls (negative = overlap)."""
    idx = np.nonzero(s.on_table)[0]
    if len(idx) < 2:
        return np.inf
    p = s.pos[idx]
    d = np.hypot(*(p[None, :, :] - p[:, None, :]).transpose(2, 0, 1))
    np.fill_diagonal(d, np.inf)
    return float(d.min() - table.ball_diameter_m)
