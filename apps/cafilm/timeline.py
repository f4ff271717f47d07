"""The automaton's generations as the film sees them: every live cell of generations 0..N,
in cells relative to the pattern's starting corner (so the board's coordinates stay small
wherever the engine placed the pattern), taken through the engine's public API only."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

MARGIN = 2  # cells of board round everything the run ever occupied
MAX_CELLS = 200_000  # live cells over a whole film: each one is an actor in every frame
MAX_BOARD = 4_000_000  # cells of board (a 2000 x 2000 square): its albedo is held per cell


class TimelineError(ValueError):
    pass


@dataclass(frozen=True, eq=False)
class Generation:
    cols: np.ndarray  # int64
    rows: np.ndarray
    states: np.ndarray

    def as_dict(self) -> dict[tuple[int, int], int]:
        return {(int(c), int(r)): int(s) for c, r, s in zip(self.cols, self.rows, self.states)}


@dataclass(frozen=True, eq=False)
class Timeline:
    generations: tuple[Generation, ...]  # index g = generation g
    floor: tuple[int, int, int, int]  # col0, row0, col1, row1 (exclusive), with a margin

    @property
    def last(self) -> int:
        return len(self.generations) - 1


def record(engine: object, generations: int) -> Timeline:
    """Step ``engine`` (apps.ca.engine.Engine) ``generations`` times, keeping each state."""
    xs, ys, ts = engine.cells()
    x0 = int(xs.min()) if len(xs) else 0
    y0 = int(ys.min()) if len(ys) else 0
    gens = [Generation(xs - x0, ys - y0, ts.copy())]
    total = len(xs)
    for _ in range(generations):
        engine.step(1)
        xs, ys, ts = engine.cells()
        total += len(xs)
        if total > MAX_CELLS:
            raise TimelineError(f"more than {MAX_CELLS} live cells over the film's "
                                f"generations (at generation {len(gens)}): film fewer "
                                "generations or a smaller pattern")
        gens.append(Generation(xs - x0, ys - y0, ts.copy()))
    floor = _floor(gens)
    area = (floor[2] - floor[0]) * (floor[3] - floor[1])
    if area > MAX_BOARD:
        raise TimelineError(f"the cells spread over {floor[2] - floor[0]} x "
                            f"{floor[3] - floor[1]} cells, more board than a film can hold "
                            f"({MAX_BOARD} cells): a smaller pattern or fewer generations")
    return Timeline(tuple(gens), floor)


def _floor(gens: list[Generation]) -> tuple[int, int, int, int]:
    cols = np.concatenate([g.cols for g in gens])
    rows = np.concatenate([g.rows for g in gens])
    if len(cols) == 0:
        return (-MARGIN, -MARGIN, MARGIN + 1, MARGIN + 1)
    return (int(cols.min()) - MARGIN, int(rows.min()) - MARGIN,
            int(cols.max()) + MARGIN + 1, int(rows.max()) + MARGIN + 1)
