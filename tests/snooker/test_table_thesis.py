"""The table's constants and markings against §6.1.1 and the standard table: sizes, the ball
set and values, where the pockets are, the spots, the D and the opening pack."""

from __future__ import annotations

import math

import numpy as np
import pytest

from camlab88.apps.snooker.layout import opening_state, pack_positions
from camlab88.apps.snooker.table import (
    BALL_NAMES,
    BALL_VALUES,
    BLACK,
    BLUE,
    BROWN,
    GREEN,
    N_BALLS,
    PINK,
    YELLOW,
    Table,
    ball_index,
)

T = Table()
IN = 0.0254


def test_playing_surface_balls_and_values_are_the_thesis_s() -> None:
    assert T.length_m == pytest.approx(12 * 12 * IN)
    assert T.width_m == pytest.approx((6 * 12 + 1.5) * IN)
    assert T.ball_diameter_m == pytest.approx((2 + 1 / 16) * IN)
    assert N_BALLS == len(BALL_NAMES) == len(BALL_VALUES) == 22
    values = dict(zip(BALL_NAMES, BALL_VALUES, strict=True))
    assert [values[c] for c in ("yellow", "green", "brown", "blue", "pink", "black")] \
        == [2, 3, 4, 5, 6, 7]
    assert sorted(v for n, v in values.items() if n.startswith("red")) == [1] * 15
    assert values["cue"] == 0


def test_checkpoint_order_cue_colours_by_value_then_reds() -> None:
    assert BALL_NAMES[:7] == ("cue", "yellow", "green", "brown", "blue", "pink", "black")
    assert all(n.startswith("red") for n in BALL_NAMES[7:])
    assert (ball_index("1"), ball_index("7"), ball_index("22")) == (0, BLACK, 21)


def test_pockets_at_the_four_corners_and_the_middle_of_the_long_sides() -> None:
    L, W = T.length_m, T.width_m
    centres = sorted((round(p.centre[0] / L * 2), round(p.centre[1] / W)) for p in T.pockets)
    assert centres == [(0, 0), (0, 1), (1, 0), (1, 1), (2, 0), (2, 1)]
    for p in T.pockets:  # each mouth at its corner or on a long side's middle
        x, y = p.centre
        assert min(abs(x), abs(x - L / 2), abs(x - L)) < 0.06
        assert min(abs(y), abs(y - W)) < 0.06


def test_baulk_line_d_and_spots_are_the_standard_markings() -> None:
    L, cy = T.length_m, T.width_m / 2
    assert T.spots[BROWN] == pytest.approx((29 * IN, cy))
    assert T.spots[BLACK] == pytest.approx((L - 12.75 * IN, cy))
    assert T.spots[BLUE] == pytest.approx((L / 2, cy))
    assert T.spots[PINK] == pytest.approx(((L / 2 + L) / 2, cy))  # midway centre - top
    for c in (YELLOW, GREEN):
        x, y = T.spots[c]
        assert x == pytest.approx(29 * IN) and abs(y - cy) == pytest.approx(11.5 * IN)
    assert T.in_d(29 * IN - 0.01, cy + 11.5 * IN - 0.02)
    assert not T.in_d(29 * IN + 0.01, cy)
    assert not T.in_d(29 * IN - 0.01, cy + 11.5 * IN + 0.01)


def test_yellow_on_the_right_of_the_d_seen_from_baulk_green_on_the_left() -> None:
    # +y is the player's left standing at the baulk end (the table's docstring)
    assert T.spots[YELLOW][1] < T.width_m / 2 < T.spots[GREEN][1]


def test_reds_in_a_touching_triangle_apex_half_a_millimetre_behind_the_pink() -> None:
    pack = pack_positions(T)
    d = T.ball_diameter_m
    px, py = T.spots[PINK]
    apex = pack[np.argmin(pack[:, 0])]
    assert apex[0] - px == pytest.approx(d + 0.0005) and apex[1] == pytest.approx(py)
    gaps = [math.dist(a, b) for i, a in enumerate(pack) for b in pack[i + 1:]]
    assert min(gaps) == pytest.approx(d)  # touching, not overlapping
    assert sum(abs(g - d) < 1e-9 for g in gaps) == 30  # a triangle of 15 has 30 contacts
    s = opening_state(T)
    assert s.pos.shape == (22, 2)


def test_default_ball_restitution_is_elastic() -> None:
    assert T.ball_restitution == 1.0
