"""A dense window of 1s straight to bit leaves and the plane's tree (what a `ca run` of a
small Life pattern needs: the pattern is placed as a grid), without a cell list."""

from __future__ import annotations

import numpy as np

from camlab88.apps.ca.hashlife.kernels import (
    BIT_LEAF_LEVEL,
    build,
    grid_leaves,
)


def grid_to_tree(top: int, left: int, grid: np.ndarray, store) -> int:  # a Store
    """The plane's node of a uint8 grid's live cells (bit leaves), its cell (0, 0) at
    (left, top); -1 if a table filled up."""
    h, w = grid.shape
    tiles = (((top + h - 1) >> BIT_LEAF_LEVEL) - (top >> BIT_LEAF_LEVEL) + 1) * \
        (((left + w - 1) >> BIT_LEAF_LEVEL) - (left >> BIT_LEAF_LEVEL) + 1)
    keys, ids = np.empty(tiles, np.int64), np.empty(tiles, np.int64)
    m = int(grid_leaves(np.int64(top), np.int64(left), np.ascontiguousarray(grid, np.uint8),
                        *store.tables, keys, ids))
    if m < 0:
        return m
    order = np.argsort(keys[:m])  # numpy's: a sort in a kernel compiles numba's quicksort
    return int(build(keys[:m][order], ids[:m][order], np.int64(m),
                     np.int64(BIT_LEAF_LEVEL), store.nodes, store.slots, store.meta))
