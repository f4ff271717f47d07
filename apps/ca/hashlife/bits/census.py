"""Statistics of a binary plane read from its tree without listing its cells (a jump can
leave a billion of them): the population and the occupied rows and columns."""

from __future__ import annotations

import numpy as np
from numba import njit

from apps.ca.hashlife.bits.convert import PLANE_LEVEL, population
from apps.ca.hashlife.bits.store import EMPTY, LEAF_LEVEL

MASK_LEVEL = 6  # nodes of 64 cells square keep their row / column occupancy in one uint64
HALF = np.uint64(0xFFFF)


def count(node: int, store) -> int:  # a BitStore
    """Live cells of the plane ``node``."""
    memo = np.full(store.count, -1, np.int64)
    return int(population(np.int64(node), np.int64(PLANE_LEVEL), memo, store.nodes,
                          store.leaves))


@njit(cache=True)
def _leaf_mask(t, axis, leaves):
    """Bit i set: row (axis 0) or column (axis 1) i of leaf t has a live cell."""
    m = np.uint64(0)
    for y in range(16):
        row = (leaves[t, y >> 2] >> np.uint64(16 * (y & 3))) & HALF
        if axis == 0:
            if row:
                m |= np.uint64(1) << np.uint64(y)
        else:
            m |= row
    return m


@njit(cache=True)
def _mask(node, level, axis, memo, done, nodes, leaves):
    """The occupancy bits of ``node`` (level <= 6): rows (axis 0), north half low bits;
    or columns (axis 1), west half low bits."""
    if level == LEAF_LEVEL:
        return _leaf_mask(node, axis, leaves)
    if done[node]:
        return memo[node]
    h = np.uint64(1) << np.uint64(level - 1)
    k = level - 1
    nw = _mask(np.int64(nodes[node, 0]), k, axis, memo, done, nodes, leaves)
    ne = _mask(np.int64(nodes[node, 1]), k, axis, memo, done, nodes, leaves)
    sw = _mask(np.int64(nodes[node, 2]), k, axis, memo, done, nodes, leaves)
    se = _mask(np.int64(nodes[node, 3]), k, axis, memo, done, nodes, leaves)
    if axis == 0:
        m = (nw | ne) | ((sw | se) << h)
    else:
        m = (nw | sw) | ((ne | se) << h)
    memo[node] = m
    done[node] = 1
    return m


@njit(cache=True)
def _occupy(node, level, y0, x0, axis, out, memo, done, nodes, leaves, meta):
    """OR the occupancy of ``node`` at (y0, x0) into ``out`` (64 rows / columns a word)."""
    if node == meta[EMPTY + level]:
        return
    if level == MASK_LEVEL:
        at = y0 if axis == 0 else x0
        out[at >> MASK_LEVEL] |= _mask(node, level, axis, memo, done, nodes, leaves)
        return
    h = np.int64(1) << (level - 1)
    k = level - 1
    nw, ne, sw, se = np.int64(nodes[node, 0]), np.int64(nodes[node, 1]), \
        np.int64(nodes[node, 2]), np.int64(nodes[node, 3])
    # Two equal quadrants side by side along the axis cover the same rows (columns): one
    # visit (a plane filled with a regular pattern is otherwise a million visits).
    _occupy(nw, k, y0, x0, axis, out, memo, done, nodes, leaves, meta)
    if axis == 0:
        if ne != nw:
            _occupy(ne, k, y0, x0 + h, axis, out, memo, done, nodes, leaves, meta)
        _occupy(sw, k, y0 + h, x0, axis, out, memo, done, nodes, leaves, meta)
        if se != sw:
            _occupy(se, k, y0 + h, x0 + h, axis, out, memo, done, nodes, leaves, meta)
    else:
        if sw != nw:
            _occupy(sw, k, y0 + h, x0, axis, out, memo, done, nodes, leaves, meta)
        _occupy(ne, k, y0, x0 + h, axis, out, memo, done, nodes, leaves, meta)
        if se != ne:
            _occupy(se, k, y0 + h, x0 + h, axis, out, memo, done, nodes, leaves, meta)


def occupied(node: int, axis: int, store) -> np.ndarray:  # a BitStore
    """Sorted indices of the rows (axis 0) or columns (axis 1) holding a live cell."""
    words = np.zeros(1 << (PLANE_LEVEL - MASK_LEVEL), np.uint64)
    memo = np.zeros(store.count, np.uint64)
    done = np.zeros(store.count, np.uint8)
    _occupy(np.int64(node), np.int64(PLANE_LEVEL), np.int64(0), np.int64(0), np.int64(axis),
            words, memo, done, store.nodes, store.leaves, store.meta)
    bits = np.unpackbits(words.view(np.uint8), bitorder="little")
    return np.flatnonzero(bits).astype(np.int64)
