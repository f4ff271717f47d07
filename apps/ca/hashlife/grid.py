"""Leaves to the plane's level-16 tree, and a dense window of 1s straight to bit leaves
(what a `ca run` of a small Life pattern needs: the pattern is placed as a grid)."""

from __future__ import annotations

import numpy as np

from apps.ca.hashlife.store import BIT_LEAF_LEVEL, EMPTY, META_T, TABLES, join, leaf
from base.kernel_set import KernelSet

kernels = KernelSet(__name__, sources=("apps.ca.hashlife.store",))

PLANE_LEVEL = 16
INTS = "int64[::1]"


@kernels.kernel
def levels(keys, ids, n, level, nodes, slots, meta):
    """The plane's node above ``n`` nodes (or leaves) of ``level``, sorted by their Morton
    keys (distinct): each level groups runs of equal key >> 2 into a parent, absent
    quadrants empty; -1 if the table is full.  Overwrites keys and ids."""
    if n == 0:
        return np.int64(meta[EMPTY + PLANE_LEVEL])
    quads = np.empty(4, np.int64)
    for lv in range(level, PLANE_LEVEL):
        m = 0
        i = 0
        while i < n:
            parent = keys[i] >> 2
            quads[:] = meta[EMPTY + lv]
            while i < n and keys[i] >> 2 == parent:
                quads[keys[i] & 3] = ids[i]
                i += 1
            node = join(quads[0], quads[1], quads[2], quads[3], np.int64(lv + 1), nodes,
                        slots, meta)
            if node < 0:
                return np.int64(-1)
            keys[m] = parent
            ids[m] = node
            m += 1
        n = m
    return np.int64(ids[0])


@kernels.kernel(inline="always")
def tile_key(tx, ty, bits):
    """Interleaved bits (x in the even bits): sorting by it groups every quadtree square."""
    m = np.int64(0)
    for bit in range(bits):
        m |= ((tx >> bit) & 1) << (2 * bit)
        m |= ((ty >> bit) & 1) << (2 * bit + 1)
    return m


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
            words[:] = 0
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
