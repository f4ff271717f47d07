"""Cell lists to the plane's tree, for either kind of leaf: a sparse pattern's cells (no
dense window) into leaves and levels, and whether live cells lie near the wrapping plane's
seam.  Their own module and kernel group: a `ca run --json` of a small Life pattern (built
from its dense window) never compiles them; the first run that needs them announces them.
The way back, a plane's cells listed, is ``listing``."""

from __future__ import annotations

import numpy as np
from camlab88.apps.ca.hashlife.grid import PLANE_LEVEL, levels, tile_key
from camlab88.apps.ca.hashlife.store import (
    EMPTY,
    LEAF,
    LEAVES,
    META_T,
    NODES,
    TABLES,
    WALL,
    leaf,
)
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__, sources=(
    "camlab88.apps.ca.hashlife.grid",
    "camlab88.apps.ca.hashlife.store",
))

INTS = "int64[::1]"


@kernels.export(f"void({INTS}, {INTS}, int64, {INTS})")
def morton(xs, ys, shift, keys):
    """Morton keys of the leaves (of 2**shift cells square) holding the cells, into keys."""
    for i in range(xs.shape[0]):
        keys[i] = tile_key(xs[i] >> shift, ys[i] >> shift, PLANE_LEVEL - shift)


# The arrays come from Python and are written over: no allocation here (numba's compiled
# numpy allocations and slice assignments were a fifth of this kernel's first compile).
@kernels.export(f"int64({INTS}, {INTS}, {INTS}, uint64[:, ::1], {TABLES})")
def from_cells(keys, xs, ys_or_values, words, nodes, slots, leaves, lslots, meta):
    """The plane's node from cells sorted by leaf key (``morton``): value leaves are the
    cells' values (``ys_or_values``; keys distinct), bit leaves are made from the cells'
    low bits (``xs``, ``ys_or_values``: columns and rows; ``words``: one leaf's rows); then
    the levels above; -1 if a table is full.  Overwrites keys and ys_or_values."""
    n = keys.shape[0]
    low = meta[LEAF]
    if low == 0:
        return levels(keys, ys_or_values, n, low, nodes, slots, meta)
    m = 0
    i = 0
    while i < n:  # leaf m's key and id go where the cells read already were (m <= i)
        key = keys[i]
        for w in range(8):
            words[0, w] = 0
        while i < n and keys[i] == key:
            y, x = ys_or_values[i] & 15, xs[i] & 15
            words[0, y >> 2] |= np.uint64(1) << np.uint64(16 * (y & 3) + x)
            i += 1
        t = leaf(words, 0, 0, leaves, lslots, meta)
        if t < 0:
            return np.int64(-1)
        keys[m] = key
        ys_or_values[m] = t
        m += 1
    return levels(keys, ys_or_values, np.int64(m), low, nodes, slots, meta)


@kernels.export("boolean(int64, int64, int64, int64, int64, int64, int64, int64, "
                f"{NODES}, {LEAVES}, {META_T})")
def any_live(node, level, y0, x0, top, bottom, left, right, nodes, leaves, meta):
    """Whether ``node`` (its corner at y0, x0) has a live cell in rows top..bottom-1,
    columns left..right-1."""
    side = np.int64(1) << level
    if (node == meta[EMPTY + level] or y0 >= bottom or y0 + side <= top or x0 >= right
            or x0 + side <= left):
        return False
    if level == meta[LEAF]:
        if level == 0:
            return 0 < node < WALL
        for y in range(max(top - y0, 0), min(bottom - y0, 16)):
            row = (leaves[node, y >> 2] >> np.uint64(16 * (y & 3))) & np.uint64(0xFFFF)
            for x in range(max(left - x0, 0), min(right - x0, 16)):
                if (row >> np.uint64(x)) & np.uint64(1):
                    return True
        return False
    h = side >> 1
    k = level - 1
    for q in range(4):
        if any_live(np.int64(nodes[node, q]), k, y0 + h * (q >> 1), x0 + h * (q & 1), top,
                     bottom, left, right, nodes, leaves, meta):
            return True
    return False


def to_tree(xs: np.ndarray, ys: np.ndarray, ts: np.ndarray, store) -> int:  # a Store
    """The plane's node of the cells at (xs, ys) of life-forms ts (all 1 for bit leaves);
    -1 if a table filled up."""
    xs = np.ascontiguousarray(xs, np.int64)
    ys = np.ascontiguousarray(ys, np.int64)
    low = store.leaf_level
    keys = np.empty(xs.shape[0], np.int64)
    morton(xs, ys, np.int64(low), keys)
    order = np.argsort(keys, kind="stable")
    second = ys if low else np.ascontiguousarray(ts, np.int64)
    # (fancy indexing copies: the kernel may write over keys and the second array)
    return int(from_cells(keys[order], xs[order], second[order], np.zeros((1, 8), np.uint64),
                          *store.tables))


def near_seam(node: int, distance: int, store) -> bool:  # a Store
    """Whether the plane ``node`` has a live cell within ``distance`` of the wrapping
    plane's seam (the first or last ``distance`` rows or columns)."""
    side = 1 << PLANE_LEVEL
    d = min(int(distance), side)
    strips = ((0, d, 0, side), (side - d, side, 0, side), (0, side, 0, d),
              (0, side, side - d, side))
    plane, zero = np.int64(PLANE_LEVEL), np.int64(0)
    return any(any_live(np.int64(node), plane, zero, zero, *(np.int64(v) for v in strip),
                        store.nodes, store.leaves, store.meta) for strip in strips)
