"""The generations a film records, through the engine's public API only (cells, step)."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.cafilm.timeline import MARGIN, TimelineError, record


class _Engine:
    """Cells drift one column right a generation (and a far cell, when asked)."""

    def __init__(self, far: int = 0) -> None:
        self.g, self.far = 0, far

    def cells(self):
        xs = [1000 + self.g, 1001 + self.g] + ([1000 + self.far] if self.far else [])
        ys = [500, 501] + ([500 + self.far] if self.far else [])
        return (np.array(xs, np.int64), np.array(ys, np.int64),
                np.ones(len(xs), np.int64))

    def step(self, n: int = 1) -> None:
        self.g += n


def test_cells_are_kept_relative_to_the_pattern_and_the_board_holds_every_generation() -> None:
    t = record(_Engine(), 3)
    assert t.last == 3
    assert t.generations[0].cols.tolist() == [0, 1] and t.generations[0].rows.tolist() == [0, 1]
    assert t.generations[3].cols.tolist() == [3, 4]
    assert t.floor == (-MARGIN, -MARGIN, 4 + MARGIN + 1, 1 + MARGIN + 1)


def test_cells_spread_too_far_for_a_board_are_refused_in_words() -> None:
    with pytest.raises(TimelineError, match="more board than a film can hold"):
        record(_Engine(far=5000), 1)
