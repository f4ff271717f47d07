"""The state of the plane as one algorithm holds it (after Golly's ``lifealgo``, where each
algorithm owns its universe): the engine keeps exactly one universe at a time, and the
algorithm that steps it decides its form.

* :class:`CellList` — live cells as three sorted int64 arrays (the direct engine's sparse
  form, thesis figure 7.10);
* :class:`DenseGrid` — a uint8 window of life-forms (the direct engine's dense path);
* a HashLife tree (apps/ca/hashlife/tree.py) — a node of a rule set's table.

What the engine asks of any of them: population, counts per life-form, the occupied rows
and columns (for the bounding box), the cell list, and a dense window if there is one.
Edits go to a cell list: the engine converts the universe first.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from camlab88.apps.ca import grid_stats

SIDE = 65536


class Universe(Protocol):
    def population(self) -> int:
        """Live cells."""

    def by_type(self, forms: int) -> dict[int, int]:
        """{life-form: cells} of the forms present (``forms``: the rules' largest)."""

    def occupied(self) -> tuple[np.ndarray, np.ndarray]:
        """(columns, rows) that hold a live cell, sorted."""

    def cells(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(ys, xs, types) of the live cells row by row (read only: do not modify)."""

    def window(self) -> tuple[int, int, np.ndarray] | None:
        """(top row, left column, uint8 grid) if the universe is a dense grid."""


def _empty() -> np.ndarray:
    return np.zeros(0, np.int64)


def distinct(values: np.ndarray) -> np.ndarray:
    """The sorted distinct values: ``np.unique`` without its masked-array check, whose first
    use imports numpy.ma (~20 ms of a short run's start)."""
    s = np.sort(values)
    if s.shape[0] < 2:
        return s
    keep = np.empty(s.shape[0], np.bool_)
    keep[0] = True
    np.not_equal(s[1:], s[:-1], out=keep[1:])
    return s[keep]


@dataclass(eq=False)
class CellList:
    """Live cells sorted row by row, then column (each position once)."""

    ys: np.ndarray = field(default_factory=_empty)
    xs: np.ndarray = field(default_factory=_empty)
    ts: np.ndarray = field(default_factory=_empty)

    def population(self) -> int:
        return int(self.ts.shape[0])

    def by_type(self, forms: int) -> dict[int, int]:
        types, counts = np.unique(self.ts, return_counts=True)
        return {int(t): int(c) for t, c in zip(types, counts)}

    def occupied(self) -> tuple[np.ndarray, np.ndarray]:
        return distinct(self.xs), distinct(self.ys)

    def cells(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return self.ys, self.xs, self.ts

    def window(self) -> None:
        return None

    def is_dense(self, min_fill: int) -> bool:
        """At least 1/``min_fill`` of the cells' box is alive."""
        n = self.ts.shape[0]
        if n == 0:
            return False
        box = (int(self.ys[-1]) - int(self.ys[0]) + 1) * (int(self.xs.max())
                                                         - int(self.xs.min()) + 1)
        return n * min_fill >= box


@dataclass(eq=False)
class DenseGrid:
    """A window of the plane as a uint8 grid of life-forms, its cell (0, 0) at (x0, y0)."""

    y0: int
    x0: int
    grid: np.ndarray
    pop: int
    _cells: tuple[np.ndarray, np.ndarray, np.ndarray] | None = field(default=None,
                                                                     repr=False)

    def population(self) -> int:
        return self.pop

    def by_type(self, forms: int) -> dict[int, int]:  # counted on the grid, no list made
        return grid_stats.by_type(self.grid)

    def occupied(self) -> tuple[np.ndarray, np.ndarray]:
        return (np.flatnonzero(self.grid.any(axis=0)) + self.x0,
                np.flatnonzero(self.grid.any(axis=1)) + self.y0)

    def cells(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        if self._cells is None:
            r, c = np.nonzero(self.grid)  # row-major order: already sorted
            self._cells = (r.astype(np.int64) + self.y0, c.astype(np.int64) + self.x0,
                           self.grid[r, c].astype(np.int64))
        return self._cells

    def window(self) -> tuple[int, int, np.ndarray]:
        return self.y0, self.x0, self.grid
