"""A dense window of 1s straight to bit leaves and the plane's tree (what a `ca run` of a
small Life pattern needs: the pattern is placed as a grid), without a cell list."""

from __future__ import annotations

import numpy as np
from camlab88.apps.ca.hashlife.grid import INTS, PLANE_LEVEL, levels, tile_key
from camlab88.apps.ca.hashlife.store import BIT_LEAF_LEVEL, META_T, TABLES, leaf
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__, sources=("camlab88.apps.ca.hashlife.grid",
                                        "camlab88.apps.ca.hashlife.store"))


@kernels.export(f"int64(int64, int64, uint8[:, ::1], {TABLES}, {INTS}, {INTS})")
def grid_leaves(top, left, grid, nodes, slots, leaves, lslots, meta, keys, ids):
    """Each 16 x 16 tile of the plane a uint8 grid (nonzero = live, its cell (0, 0) at
    (left, top)) covers, as a bit leaf straight from the grid's bytes (no cell list): their
    Morton keys and ids into ``keys`` and ``ids``; returns how many (-1: table full)."""
    h, w = grid.shape
    ty0, ty1 = top >> BIT_LEAF_LEVEL, (top + h - 1) >> BIT_LEAF_LEVEL
    tx0, tx1 = left >> BIT_LEAF_LEVEL, (left + w - 1) >> BIT_LEAF_LEVEL
    words = np.zeros((1, 8), np.uint64)
    m = 0
    for ty in range(ty0, ty1 + 1):
        for tx in range(tx0, tx1 + 1):
            for i in range(8):  # (a slice assignment compiles numpy's broadcasting)
                words[0, i] = 0
            live = False
            for y in range(16):
                gy = (ty << BIT_LEAF_LEVEL) + y - top
                if gy < 0 or gy >= h:
                    continue
                row = np.uint64(0)
                for x in range(16):
                    gx = (tx << BIT_LEAF_LEVEL) + x - left
                    if gx >= 0 and gx < w and grid[gy, gx] != 0:
                        row |= np.uint64(1) << np.uint64(x)
                if row:
                    live = True
                    words[0, y >> 2] |= row << np.uint64(16 * (y & 3))
            if not live:
                continue
            t = leaf(words, 0, 0, leaves, lslots, meta)
            if t < 0:
                return np.int64(-1)
            keys[m] = tile_key(tx, ty, PLANE_LEVEL - BIT_LEAF_LEVEL)
            ids[m] = t
            m += 1
    return np.int64(m)


@kernels.export(f"int64({INTS}, {INTS}, int64, int64, int32[:, ::1], int32[::1], {META_T})")
def build(keys, ids, n, level, nodes, slots, meta):
    """``levels`` for Python."""
    return levels(keys, ids, n, level, nodes, slots, meta)


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
