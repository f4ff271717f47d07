"""Leaves to the plane's level-16 tree (from their Morton keys), for either kind of leaf."""

from __future__ import annotations

import numpy as np

from apps.ca.hashlife.store import EMPTY, META_T, join
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


@kernels.export(f"int64({INTS}, {INTS}, int64, int64, int32[:, ::1], int32[::1], {META_T})")
def build(keys, ids, n, level, nodes, slots, meta):
    """``levels`` for Python."""
    return levels(keys, ids, n, level, nodes, slots, meta)
