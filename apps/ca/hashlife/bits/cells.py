"""Cell lists to the binary path's plane tree and back: a sparse pattern's cells (no dense
window) into leaves and levels, a plane's live cells out (for pictures and cell queries).
Their own module and kernel group: a `ca run --json` of a small pattern (built from its dense
window) never compiles them; the first run that needs them announces them.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from apps.ca.hashlife.bits.convert import PLANE_LEVEL, TILES, _levels, population
from apps.ca.hashlife.bits.store import EMPTY, LEAF_LEVEL, N_NODES, leaf


@njit(cache=True)
def _leaf_keys(xs, ys):
    """Morton keys of the leaves holding the cells (x in the even bits)."""
    keys = np.empty(xs.shape[0], np.int64)
    for i in range(xs.shape[0]):
        x, y, m = xs[i] >> LEAF_LEVEL, ys[i] >> LEAF_LEVEL, np.int64(0)
        for bit in range(TILES):
            m |= ((x >> bit) & 1) << (2 * bit)
            m |= ((y >> bit) & 1) << (2 * bit + 1)
        keys[i] = m
    return keys


@njit(cache=True)
def build(keys, xs, ys, nodes, slots, leaves, lslots, meta):
    """The plane's node from cells sorted by leaf key: the leaves first, then each level
    groups runs of equal key >> 2 into a parent, absent quadrants empty; -1 if full."""
    n = keys.shape[0]
    if n == 0:
        return np.int64(meta[EMPTY + PLANE_LEVEL])
    lkeys = np.empty(n, np.int64)
    ids = np.empty(n, np.int64)
    words = np.zeros((1, 8), np.uint64)
    m = 0
    i = 0
    while i < n:
        key = keys[i]
        words[:] = 0
        while i < n and keys[i] == key:
            y, x = ys[i] & 15, xs[i] & 15
            words[0, y >> 2] |= np.uint64(1) << np.uint64(16 * (y & 3) + x)
            i += 1
        t = leaf(words, 0, 0, leaves, lslots, meta)
        if t < 0:
            return np.int64(-1)
        lkeys[m] = key
        ids[m] = t
        m += 1
    return _levels(lkeys, ids, np.int64(m), nodes, slots, meta)


@njit(cache=True)
def _emit(node, level, y0, x0, nodes, leaves, meta, out, n):
    """Append (y, x) of the live cells of ``node`` to ``out`` from row ``n``."""
    if node == meta[EMPTY + level]:
        return n
    if level == LEAF_LEVEL:
        for y in range(16):
            row = (leaves[node, y >> 2] >> np.uint64(16 * (y & 3))) & np.uint64(0xFFFF)
            for x in range(16):
                if (row >> np.uint64(x)) & np.uint64(1):
                    out[n, 0], out[n, 1] = y0 + y, x0 + x
                    n += 1
        return n
    h = np.int64(1) << (level - 1)
    k = level - 1
    n = _emit(np.int64(nodes[node, 0]), k, y0, x0, nodes, leaves, meta, out, n)
    n = _emit(np.int64(nodes[node, 1]), k, y0, x0 + h, nodes, leaves, meta, out, n)
    n = _emit(np.int64(nodes[node, 2]), k, y0 + h, x0, nodes, leaves, meta, out, n)
    return _emit(np.int64(nodes[node, 3]), k, y0 + h, x0 + h, nodes, leaves, meta, out, n)


@njit(cache=True)
def _cells(node, nodes, leaves, meta):
    top = np.int64(PLANE_LEVEL)
    memo = np.full(meta[N_NODES], -1, np.int64)
    out = np.empty((population(node, top, memo, nodes, leaves), 2), np.int64)
    _emit(node, top, np.int64(0), np.int64(0), nodes, leaves, meta, out, np.int64(0))
    return out


def cells(node: int, nodes: np.ndarray, leaves: np.ndarray, meta: np.ndarray) -> np.ndarray:
    """(y, x) rows of the plane node's live cells, sorted row by row (by numpy: a sort
    inside a kernel compiles numba's quicksort, seconds of a first run)."""
    out = _cells(np.int64(node), nodes, leaves, meta)
    return out[np.argsort(out[:, 0] * (1 << PLANE_LEVEL) + out[:, 1])]


def to_tree(xs: np.ndarray, ys: np.ndarray, store) -> int:  # a BitStore
    """The plane's node of the cells at (xs, ys); -1 if a table filled up."""
    xs = np.ascontiguousarray(xs, np.int64)
    ys = np.ascontiguousarray(ys, np.int64)
    keys = _leaf_keys(xs, ys)
    order = np.argsort(keys, kind="stable")
    return int(build(keys[order], xs[order], ys[order], store.nodes, store.slots,
                     store.leaves, store.lslots, store.meta))
