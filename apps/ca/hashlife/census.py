"""Statistics of a plane read from its tree without listing its cells (a jump can leave a
billion of them): cells per life-form and the occupied rows and columns, for either kind of
leaf (the leaf level in the store's meta says which: 0, a value; else a bit leaf)."""

from __future__ import annotations

import numpy as np
from camlab88.apps.ca.hashlife.store import EMPTY, LEAF, LEAVES, META_T, NODES, WALL
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__)

PLANE_LEVEL = 16
MASK_LEVEL = 6  # nodes of 64 cells square keep their row / column occupancy in one uint64
HALF = np.uint64(0xFFFF)


@kernels.kernel(inline="always")
def _popcount(w):
    w = w - ((w >> np.uint64(1)) & np.uint64(0x5555555555555555))
    w = (w & np.uint64(0x3333333333333333)) + ((w >> np.uint64(2)) & np.uint64(0x3333333333333333))
    w = (w + (w >> np.uint64(4))) & np.uint64(0x0F0F0F0F0F0F0F0F)
    return np.int64((w * np.uint64(0x0101010101010101)) >> np.uint64(56))


@kernels.kernel(inline="always")
def _leaf_count(t, form, leaves, meta):
    """Cells of leaf ``t`` holding life-form ``form`` (0: any live cell)."""
    if meta[LEAF] == 0:
        live = 0 < t < WALL
        return np.int64(1 if live and (form == 0 or t == form) else 0)
    if form > 1:
        return np.int64(0)
    return (_popcount(leaves[t, 0]) + _popcount(leaves[t, 1]) + _popcount(leaves[t, 2])
            + _popcount(leaves[t, 3]))


@kernels.export(f"int64(int64, int64, int64, int64[::1], {NODES}, {LEAVES}, {META_T})")
def count(node, level, form, memo, nodes, leaves, meta):
    """Cells of ``node`` holding life-form ``form`` (0: any live cell); each node counted
    once (memo -1 = not yet)."""
    if level == meta[LEAF]:
        return _leaf_count(node, form, leaves, meta)
    if node == meta[EMPTY + level]:
        return np.int64(0)
    m = memo[node]
    if m >= 0:
        return m
    total = np.int64(0)
    for q in range(4):
        total += count(np.int64(nodes[node, q]), level - 1, form, memo, nodes, leaves, meta)
    memo[node] = total
    return total


@kernels.kernel
def _leaf_mask(t, axis, leaves, meta):
    """Bit i set: row (axis 0) or column (axis 1) i of leaf t has a live cell."""
    if meta[LEAF] == 0:
        return np.uint64(1) if 0 < t < WALL else np.uint64(0)
    m = np.uint64(0)
    for y in range(16):
        row = (leaves[t, y >> 2] >> np.uint64(16 * (y & 3))) & HALF
        if axis == 0:
            if row:
                m |= np.uint64(1) << np.uint64(y)
        else:
            m |= row
    return m


@kernels.kernel
def _mask(node, level, axis, memo, done, nodes, leaves, meta):
    """The occupancy bits of ``node`` (level <= 6): rows (axis 0), north half low bits;
    or columns (axis 1), west half low bits."""
    if level == meta[LEAF]:
        return _leaf_mask(node, axis, leaves, meta)
    if done[node]:
        return memo[node]
    h = np.uint64(1) << np.uint64(level - 1)
    k = level - 1
    nw = _mask(np.int64(nodes[node, 0]), k, axis, memo, done, nodes, leaves, meta)
    ne = _mask(np.int64(nodes[node, 1]), k, axis, memo, done, nodes, leaves, meta)
    sw = _mask(np.int64(nodes[node, 2]), k, axis, memo, done, nodes, leaves, meta)
    se = _mask(np.int64(nodes[node, 3]), k, axis, memo, done, nodes, leaves, meta)
    if axis == 0:
        m = (nw | ne) | ((sw | se) << h)
    else:
        m = (nw | sw) | ((ne | se) << h)
    memo[node] = m
    done[node] = 1
    return m


# Exported itself (no wrapper for the plane's level: each kernel Python calls is another
# compile of everything it calls, ~0.2 s of a first run).
@kernels.export(f"void(int64, int64, int64, int64, int64, uint64[::1], uint64[::1], uint8[::1], "
                f"{NODES}, {LEAVES}, {META_T})")
def occupy(node, level, y0, x0, axis, out, memo, done, nodes, leaves, meta):
    """OR the occupancy of ``node`` at (y0, x0) into ``out`` (64 rows / columns a word)."""
    if node == meta[EMPTY + level]:
        return
    if level == MASK_LEVEL:
        at = y0 if axis == 0 else x0
        out[at >> MASK_LEVEL] |= _mask(node, level, axis, memo, done, nodes, leaves, meta)
        return
    h = np.int64(1) << (level - 1)
    k = level - 1
    nw, ne, sw, se = np.int64(nodes[node, 0]), np.int64(nodes[node, 1]), \
        np.int64(nodes[node, 2]), np.int64(nodes[node, 3])
    # Two equal quadrants side by side along the axis cover the same rows (columns): one
    # visit (a plane filled with a regular pattern is otherwise a million visits).
    occupy(nw, k, y0, x0, axis, out, memo, done, nodes, leaves, meta)
    if axis == 0:
        if ne != nw:
            occupy(ne, k, y0, x0 + h, axis, out, memo, done, nodes, leaves, meta)
        occupy(sw, k, y0 + h, x0, axis, out, memo, done, nodes, leaves, meta)
        if se != sw:
            occupy(se, k, y0 + h, x0 + h, axis, out, memo, done, nodes, leaves, meta)
    else:
        if sw != nw:
            occupy(sw, k, y0 + h, x0, axis, out, memo, done, nodes, leaves, meta)
        occupy(ne, k, y0, x0 + h, axis, out, memo, done, nodes, leaves, meta)
        if se != ne:
            occupy(se, k, y0 + h, x0 + h, axis, out, memo, done, nodes, leaves, meta)


def cells_of(node: int, form: int, store) -> int:  # a Store
    """Cells of the plane ``node`` holding life-form ``form`` (0: any live cell)."""
    memo = np.full(store.count, -1, np.int64)
    return int(count(np.int64(node), np.int64(PLANE_LEVEL), np.int64(form), memo, store.nodes,
                     store.leaves, store.meta))


def by_type(node: int, forms: int, store) -> dict[int, int]:
    """{life-form: cells} of the plane ``node`` for life-forms 1..forms (those present)."""
    if store.leaf_level:  # bit leaves hold only 1s
        n = cells_of(node, 1, store)
        return {1: n} if n else {}
    found = {}
    for t in range(1, forms + 1):
        n = cells_of(node, t, store)
        if n:
            found[t] = n
    return found


def occupied(node: int, axis: int, store) -> np.ndarray:  # a Store
    """Sorted indices of the rows (axis 0) or columns (axis 1) holding a live cell."""
    words = np.zeros(1 << (PLANE_LEVEL - MASK_LEVEL), np.uint64)
    memo = np.zeros(store.count, np.uint64)
    done = np.zeros(store.count, np.uint8)
    occupy(np.int64(node), np.int64(PLANE_LEVEL), np.int64(0), np.int64(0), np.int64(axis), words,
           memo, done, store.nodes, store.leaves, store.meta)
    bits = np.unpackbits(words.view(np.uint8), bitorder="little")
    return np.flatnonzero(bits).astype(np.int64)
