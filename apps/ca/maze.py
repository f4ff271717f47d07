"""Mazes for the maze runner of figure 7.8 (section 7.4.1), with their shortest paths.

The maze is a perfect maze of one-cell corridors (walls are life-form 1), carved by a seeded
depth-first search, with an entrance gap in the top wall and an exit gap in the bottom wall.
The runner (head 2, tail 3) starts in the entrance.  The runner splits at every junction and
dies in dead ends, so a head first reaches the exit after exactly the shortest path length:
that is what the tests check.
"""

from __future__ import annotations

import random
from collections import deque

from camlab88.apps.ca.patterns import Pattern

WALL, HEAD, TAIL = 1, 2, 3


def carve(cols: int, rows: int, seed: int) -> list[list[bool]]:
    """Open (True) / wall (False) grid of (2*rows+1) x (2*cols+1) cells."""
    h, w = 2 * rows + 1, 2 * cols + 1
    open_ = [[False] * w for _ in range(h)]
    rng = random.Random(seed)
    stack = [(0, 0)]
    seen = {(0, 0)}
    open_[1][1] = True
    while stack:
        cx, cy = stack[-1]
        nxt = [(cx + dx, cy + dy, dx, dy) for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1))
               if 0 <= cx + dx < cols and 0 <= cy + dy < rows and (cx + dx, cy + dy) not in seen]
        if not nxt:
            stack.pop()
            continue
        nx, ny, dx, dy = rng.choice(nxt)
        open_[2 * cy + 1 + dy][2 * cx + 1 + dx] = True
        open_[2 * ny + 1][2 * nx + 1] = True
        seen.add((nx, ny))
        stack.append((nx, ny))
    open_[0][1] = True  # entrance
    open_[h - 1][w - 2] = True  # exit
    return open_


def build(cols: int = 12, rows: int = 8, seed: int = 1987) -> tuple[Pattern, tuple[int, int],
                                                                       int]:
    """(pattern, exit cell, generations a head needs to reach the exit).

    Pattern coordinates: the maze's top-left wall at (0, 1); the runner's tail above the
    entrance at (1, 0) and its head in the entrance at (1, 1).
    """
    grid = carve(cols, rows, seed)
    h, w = len(grid), len(grid[0])
    cells = [(x, y + 1, WALL) for y in range(h) for x in range(w) if not grid[y][x]]
    cells += [(1, 0, TAIL), (1, 1, HEAD)]
    exit_cell = (w - 2, h)  # the exit gap, in pattern coordinates
    # Breadth-first search over open cells from the head's cell.
    dist = {(1, 1): 0}
    queue = deque([(1, 1)])
    while queue:
        x, y = queue.popleft()
        for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            nx, ny = x + dx, y + dy
            if 1 <= ny <= h and 0 <= nx < w and grid[ny - 1][nx] and (nx, ny) not in dist:
                dist[(nx, ny)] = dist[(x, y)] + 1
                queue.append((nx, ny))
    p = Pattern.from_cells(cells, ref=(0, 0), name=f"maze {cols}x{rows} seed {seed}",
                           rule="maze")
    return p, exit_cell, dist[exit_cell]


def corner() -> Pattern:
    """A runner beside a wall that turns a corner: figure 7.7's "movement of a maze runner
    over four generations" (the runner's head reaches the corner at generation 2 and turns
    down it at 3). The wall's top-left cell is the reference point."""
    cells = [(x, 0, WALL) for x in range(7)] + [(6, y, WALL) for y in range(1, 7)]
    cells += [(2, 1, TAIL), (3, 1, HEAD)]
    return Pattern.from_cells(cells, ref=(0, 0), name="maze runner at a corner", rule="maze",
                              comments=["figure 7.7: a runner (head red, tail blue) along a "
                                        "wall (green) that turns a corner"])
