"""A plane's live cells listed, for either kind of leaf (pictures, cell queries, saved
states).  Its own module and kernel group: a `ca run` that prints only the census never
compiles it."""

from __future__ import annotations

import numpy as np
from camlab88.apps.ca.hashlife.census import count
from camlab88.apps.ca.hashlife.grid import PLANE_LEVEL
from camlab88.apps.ca.hashlife.store import EMPTY, LEAF, LEAVES, META_T, N_NODES, NODES, WALL
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__, sources=("camlab88.apps.ca.hashlife.census",
                                        "camlab88.apps.ca.hashlife.store"))


@kernels.kernel
def _emit(node, level, y0, x0, nodes, leaves, meta, out, n):
    """Append (y, x, value) of the live cells of ``node`` to ``out`` from row ``n``."""
    if level == meta[LEAF]:
        if level == 0:
            if 0 < node < WALL:
                out[n, 0], out[n, 1], out[n, 2] = y0, x0, node
                n += 1
            return n
        for y in range(16):
            row = (leaves[node, y >> 2] >> np.uint64(16 * (y & 3))) & np.uint64(0xFFFF)
            for x in range(16):
                if (row >> np.uint64(x)) & np.uint64(1):
                    out[n, 0], out[n, 1], out[n, 2] = y0 + y, x0 + x, 1
                    n += 1
        return n
    if node == meta[EMPTY + level]:
        return n
    h = np.int64(1) << (level - 1)
    k = level - 1
    n = _emit(np.int64(nodes[node, 0]), k, y0, x0, nodes, leaves, meta, out, n)
    n = _emit(np.int64(nodes[node, 1]), k, y0, x0 + h, nodes, leaves, meta, out, n)
    n = _emit(np.int64(nodes[node, 2]), k, y0 + h, x0, nodes, leaves, meta, out, n)
    return _emit(np.int64(nodes[node, 3]), k, y0 + h, x0 + h, nodes, leaves, meta, out, n)


@kernels.export(f"int64[:, ::1](int64, {NODES}, {LEAVES}, {META_T})")
def listing(node, nodes, leaves, meta):
    """(y, x, value) rows of the live cells of the plane ``node``, in quadtree order."""
    top = np.int64(PLANE_LEVEL)
    memo = np.full(meta[N_NODES], -1, np.int64)
    out = np.empty((count(node, top, np.int64(0), memo, nodes, leaves, meta), 3), np.int64)
    _emit(node, top, np.int64(0), np.int64(0), nodes, leaves, meta, out, np.int64(0))
    return out


def cells(node: int, store) -> tuple[np.ndarray, np.ndarray, np.ndarray]:  # a Store
    """(ys, xs, values) of the plane node's live cells, sorted row by row (by numpy: a
    sort inside a kernel compiles numba's quicksort, seconds of a first run)."""
    out = listing(np.int64(node), store.nodes, store.leaves, store.meta)
    out = out[np.argsort(out[:, 0] * (1 << PLANE_LEVEL) + out[:, 1])]
    return out[:, 0].copy(), out[:, 1].copy(), out[:, 2].copy()
