"""Live cells (all life-form 1) to the binary path's level-16 tree of the plane and back."""

from __future__ import annotations

import numpy as np
from numba import njit

from apps.ca.hashlife.bits.store import EMPTY, LEAF_LEVEL, join, leaf

PLANE_LEVEL = 16
TILES = PLANE_LEVEL - LEAF_LEVEL  # levels of nodes above the leaves


@njit(cache=True)
def _tile_key(tx, ty):
    m = np.int64(0)
    for bit in range(TILES):
        m |= ((tx >> bit) & 1) << (2 * bit)
        m |= ((ty >> bit) & 1) << (2 * bit + 1)
    return m


@njit(cache=True)
def _grid_leaves(top, left, grid, leaves, lslots, meta, lkeys, ids):
    """Each 16 x 16 tile of the plane a uint8 grid (nonzero = live, its cell (0, 0) at
    (left, top)) covers, as a leaf straight from the grid's bytes (no cell list): their
    Morton keys and ids into ``lkeys`` and ``ids``; returns how many (-1: table full)."""
    h, w = grid.shape
    ty0, ty1 = top >> LEAF_LEVEL, (top + h - 1) >> LEAF_LEVEL
    tx0, tx1 = left >> LEAF_LEVEL, (left + w - 1) >> LEAF_LEVEL
    words = np.zeros((1, 8), np.uint64)
    m = 0
    for ty in range(ty0, ty1 + 1):
        for tx in range(tx0, tx1 + 1):
            words[:] = 0
            live = False
            for y in range(16):
                gy = (ty << LEAF_LEVEL) + y - top
                if gy < 0 or gy >= h:
                    continue
                row = np.uint64(0)
                for x in range(16):
                    gx = (tx << LEAF_LEVEL) + x - left
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
            lkeys[m] = _tile_key(tx, ty)
            ids[m] = t
            m += 1
    return np.int64(m)


@njit(cache=True)
def _levels(lkeys, ids, n, nodes, slots, meta):
    """The tree above leaves ``ids`` sorted by their Morton keys ``lkeys``."""
    quads = np.empty(4, np.int64)
    for level in range(LEAF_LEVEL, PLANE_LEVEL):
        m = 0
        i = 0
        while i < n:
            parent = lkeys[i] >> 2
            quads[:] = meta[EMPTY + level]
            while i < n and lkeys[i] >> 2 == parent:
                quads[lkeys[i] & 3] = ids[i]
                i += 1
            node = join(quads[0], quads[1], quads[2], quads[3], level + 1, nodes, slots,
                        meta)
            if node < 0:
                return np.int64(-1)
            lkeys[m] = parent
            ids[m] = node
            m += 1
        n = m
    return np.int64(ids[0])


@njit(cache=True)
def _popcount(w):
    w = w - ((w >> np.uint64(1)) & np.uint64(0x5555555555555555))
    w = (w & np.uint64(0x3333333333333333)) + ((w >> np.uint64(2)) & np.uint64(0x3333333333333333))
    w = (w + (w >> np.uint64(4))) & np.uint64(0x0F0F0F0F0F0F0F0F)
    return np.int64((w * np.uint64(0x0101010101010101)) >> np.uint64(56))


@njit(cache=True)
def leaf_population(t, leaves):
    return (_popcount(leaves[t, 0]) + _popcount(leaves[t, 1]) + _popcount(leaves[t, 2])
            + _popcount(leaves[t, 3]))


@njit(cache=True)
def population(node, level, memo, nodes, leaves):
    """Live cells of ``node`` (each node counted once: memo -1 = not yet)."""
    if level == LEAF_LEVEL:
        return leaf_population(node, leaves)
    m = memo[node]
    if m >= 0:
        return m
    total = np.int64(0)
    for q in range(4):
        total += population(np.int64(nodes[node, q]), level - 1, memo, nodes, leaves)
    memo[node] = total
    return total


def grid_to_tree(top: int, left: int, grid: np.ndarray, store) -> int:
    """The plane's node of a uint8 grid's live cells, its cell (0, 0) at (left, top);
    -1 if a table filled up."""
    h, w = grid.shape
    tiles = (((top + h - 1) >> LEAF_LEVEL) - (top >> LEAF_LEVEL) + 1) * \
        (((left + w - 1) >> LEAF_LEVEL) - (left >> LEAF_LEVEL) + 1)
    lkeys, ids = np.empty(tiles, np.int64), np.empty(tiles, np.int64)
    m = int(_grid_leaves(np.int64(top), np.int64(left), np.ascontiguousarray(grid, np.uint8),
                         store.leaves, store.lslots, store.meta, lkeys, ids))
    if m <= 0:
        return m if m < 0 else int(store.meta[EMPTY + PLANE_LEVEL])
    order = np.argsort(lkeys[:m])  # numpy's: a sort in a kernel compiles numba's quicksort
    return int(_levels(lkeys[:m][order], ids[:m][order], np.int64(m), store.nodes,
                       store.slots, store.meta))
