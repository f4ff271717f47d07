"""The opening position (fig 6.1): colours on their spots, the fifteen reds in a touching
triangle behind the pink, the cue ball in the D; and the standard break-off stroke."""

from __future__ import annotations

import math

import numpy as np

from camlab88.apps.snooker.state import BallState
from camlab88.apps.snooker.table import BROWN, COLOURS, CUE, N_BALLS, PINK, REDS, Table

PACK_GAP_M = 0.0005  # the apex red sits "as near to the pink as possible without touching"


def pack_positions(table: Table) -> np.ndarray:
    d = table.ball_diameter_m
    px, py = table.spots[PINK]
    apex = px + d + PACK_GAP_M
    out = []
    for row in range(5):
        for k in range(row + 1):
            out.append((apex + row * d * math.sqrt(3.0) / 2.0, py + (k - row / 2.0) * d))
    return np.array(out)


def default_cue_position(table: Table) -> tuple[float, float]:
    """Between the brown and yellow spots, where break-offs are usually played from."""
    bx, by = table.spots[BROWN]
    return (bx, by - table.d_radius_m / 2.0)


def opening_state(table: Table, cue: tuple[float, float] | None = None) -> BallState:
    pos = np.zeros((N_BALLS, 2))
    pos[CUE] = cue if cue is not None else default_cue_position(table)
    for c in COLOURS:
        pos[c] = table.spots[c]
    pos[list(REDS)] = pack_positions(table)
    return BallState.at_rest(pos, np.ones(N_BALLS, dtype=bool))


def break_off_direction(table: Table, state: BallState) -> tuple[float, float]:
    """Aim thin at the end red of the back row on the cue ball's side of the table, the usual
    break-off (a straight line at the apex is blocked by the pink)."""
    d = table.ball_diameter_m
    corner = pack_positions(table)[10]  # back row, first ball: the y-smallest corner
    cx, cy = state.pos[CUE]
    side = -1.0 if cy <= table.width_m / 2.0 else 1.0
    target = corner if side < 0 else pack_positions(table)[14]
    tx, ty = target[0], target[1] + side * 0.8 * d  # contact at 0.8 of a ball: a thin cut
    n = math.hypot(tx - cx, ty - cy)
    return ((tx - cx) / n, (ty - cy) / n)


def break_off(table: Table, speed_m_s: float, spin_m_s: float = 0.0) -> BallState:
    state = opening_state(table)
    ux, uy = break_off_direction(table, state)
    m = state.thaw()
    m.set_velocity(CUE, ux * speed_m_s, uy * speed_m_s, spin_m_s)
    return m.freeze()
