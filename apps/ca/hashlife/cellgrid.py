"""The base case of value leaves: a node of the base level to its centre after T
generations, by running the rules (``leaf.generation``) on its cells as a grid of
life-form values.

The scratch ``G`` is the recursion's (uint64, four square planes of the base node's side,
one above the other: plane p, row y is G[p * side + y]), read here as int64: planes 0 and 1
hold this and the next generation, plane 2 node ids while a centre is built, plane 3 the
messages.  The rules arrive packed as uint64 (the recursion's one type for both kinds of
leaf) and are read as int64.
"""

from __future__ import annotations

import numpy as np
from camlab88.apps.ca.hashlife.leaf import generation
from camlab88.apps.ca.hashlife.store import LEVEL, REACH, all_tables, join
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__, _nrt=False, sources=(
    "camlab88.apps.ca.hashlife.leaf",
    "camlab88.apps.ca.hashlife.store",
    "camlab88.base.raw_views",
    "camlab88.base.raw_view_intrinsics",
))


@kernels.kernel(inline="always")
def to_grid(node, level, G, p, nodes):
    """Write the cells of ``node`` into plane ``p`` of G, splitting in place."""
    side = np.int64(1) << level
    P = p * G.shape[1]
    G[P, 0] = node
    half = side
    while half > 1:
        quarter = half >> 1
        for y in range(0, side, half):
            for x in range(0, side, half):
                n = G[P + y, x]
                G[P + y, x] = nodes[n, 0]
                G[P + y, x + quarter] = nodes[n, 1]
                G[P + y + quarter, x] = nodes[n, 2]
                G[P + y + quarter, x + quarter] = nodes[n, 3]
        half = quarter


@kernels.kernel(inline="always")
def from_grid(G, p, y0, x0, level, nodes, slots, meta):
    """The node of the 2**level square at (y0, x0) of plane ``p``, built bottom-up in
    plane 2; -1 if the table is full."""
    side = np.int64(1) << level
    P, W = p * G.shape[1], 2 * G.shape[1]
    for y in range(side):
        for x in range(side):
            G[W + y, x] = G[P + y0 + y, x0 + x]
    step = np.int64(1)
    k = np.int64(1)
    while step < side:
        for y in range(0, side, 2 * step):
            for x in range(0, side, 2 * step):
                n = join(G[W + y, x], G[W + y, x + step], G[W + y + step, x],
                         G[W + y + step, x + step], k, nodes, slots, meta)
                if n < 0:
                    return np.int64(-1)
                G[W + y, x] = n
        step *= 2
        k += 1
    return np.int64(G[W, 0])


@kernels.kernel
def advance(node, T, at):
    """Centre of base-level ``node`` after T generations (0: its centre as it is).  ``at``:
    the address of the store's meta with the tables' addresses (store.publish)."""
    nodes, slots, _, _, meta, R, G = all_tables(at)
    level = np.int64(nodes[node, LEVEL])
    n = np.int64(1) << level
    r = meta[REACH]
    cells = G.view(np.int64)
    rules = R.view(np.int64)
    to_grid(node, level, cells, np.int64(0), nodes)
    s = np.int64(0)
    for g in range(1, T + 1):
        lo = n // 4 - (T - g) * r  # only what the later generations still need
        generation(cells, s, 1 - s, lo, n - lo, rules)
        s = 1 - s
    return from_grid(cells, s, n // 4, n // 4, level - 1, nodes, slots, meta)
