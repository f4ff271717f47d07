"""Statistics of a plane read from its tree without listing its cells (a jump can leave
hundreds of millions of them): counts per life-form and the occupied rows and columns."""

from __future__ import annotations

import numpy as np
from numba import njit

from apps.ca.hashlife.convert import PLANE_LEVEL
from apps.ca.hashlife.store import LEAF_IDS

MASK_LEVEL = 6  # nodes of 64 cells square keep their row / column occupancy in one uint64


@njit(cache=True)
def _count(node, t, memo, nodes):
    """Cells of ``node`` holding life-form ``t`` (each node counted once, memo -1 = not yet)."""
    if node < LEAF_IDS:
        return np.int64(1 if node == t else 0)
    m = memo[node]
    if m >= 0:
        return m
    total = np.int64(0)
    for q in range(4):
        total += _count(np.int64(nodes[node, q]), t, memo, nodes)
    memo[node] = total
    return total


def counts(node: int, forms: int, nodes: np.ndarray, count: int) -> dict[int, int]:
    """{life-form: cells} of the plane ``node`` for life-forms 1..forms (those present)."""
    memo = np.empty(count, np.int64)
    found = {}
    for t in range(1, forms + 1):
        memo[:] = -1
        n = int(_count(np.int64(node), np.int64(t), memo, nodes))
        if n:
            found[t] = n
    return found


@njit(cache=True)
def _mask(node, level, axis, memo, done, nodes):
    """Bit i set: row (axis 0) or column (axis 1) i of ``node`` (level <= 6) has a live
    cell."""
    if level == 0:
        return np.uint64(1) if 0 < node < LEAF_IDS - 1 else np.uint64(0)
    if done[node]:
        return memo[node]
    h = np.uint64(1) << np.uint64(level - 1)
    k = level - 1
    nw = _mask(np.int64(nodes[node, 0]), k, axis, memo, done, nodes)
    ne = _mask(np.int64(nodes[node, 1]), k, axis, memo, done, nodes)
    sw = _mask(np.int64(nodes[node, 2]), k, axis, memo, done, nodes)
    se = _mask(np.int64(nodes[node, 3]), k, axis, memo, done, nodes)
    if axis == 0:  # rows: north half low bits
        m = (nw | ne) | ((sw | se) << h)
    else:
        m = (nw | sw) | ((ne | se) << h)
    memo[node] = m
    done[node] = 1
    return m


@njit(cache=True)
def _occupy(node, level, y0, x0, axis, out, memo, done, nodes, empty):
    """OR the occupancy of ``node`` at (y0, x0) into ``out`` (64 rows / columns a word)."""
    if node == empty[level]:
        return
    if level == MASK_LEVEL:
        at = y0 if axis == 0 else x0
        out[at >> MASK_LEVEL] |= _mask(node, level, axis, memo, done, nodes)
        return
    h = np.int64(1) << (level - 1)
    k = level - 1
    _occupy(np.int64(nodes[node, 0]), k, y0, x0, axis, out, memo, done, nodes, empty)
    _occupy(np.int64(nodes[node, 1]), k, y0, x0 + h, axis, out, memo, done, nodes, empty)
    _occupy(np.int64(nodes[node, 2]), k, y0 + h, x0, axis, out, memo, done, nodes, empty)
    _occupy(np.int64(nodes[node, 3]), k, y0 + h, x0 + h, axis, out, memo, done, nodes, empty)


def occupied(node: int, axis: int, nodes: np.ndarray, empty: np.ndarray,
             count: int) -> np.ndarray:
    """Sorted indices of the rows (axis 0) or columns (axis 1) holding a live cell."""
    words = np.zeros(1 << (PLANE_LEVEL - MASK_LEVEL), np.uint64)
    memo = np.zeros(count, np.uint64)
    done = np.zeros(count, np.uint8)
    _occupy(np.int64(node), np.int64(PLANE_LEVEL), np.int64(0), np.int64(0), np.int64(axis),
            words, memo, done, nodes, empty)
    bits = np.unpackbits(words.view(np.uint8), bitorder="little")
    return np.flatnonzero(bits).astype(np.int64)
