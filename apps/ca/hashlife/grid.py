"""Leaves to the plane's level-16 tree (from their Morton keys), for either kind of leaf."""

from __future__ import annotations

import numpy as np
from camlab88.apps.ca.hashlife.store import EMPTY, join
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__, sources=("camlab88.apps.ca.hashlife.store",))

PLANE_LEVEL = 16
INTS = "int64[::1]"


@kernels.kernel
def levels(keys, ids, n, level, nodes, slots, meta):
    """The plane's node above ``n`` nodes (or leaves) of ``level``, sorted by their Morton
    keys (distinct): each level groups runs of equal key >> 2 into a parent, absent
    quadrants empty; -1 if the table is full.  Overwrites keys and ids."""
    if n == 0:
        return np.int64(meta[EMPTY + PLANE_LEVEL])
    for lv in range(level, PLANE_LEVEL):
        m = 0
        i = 0
        while i < n:
            parent = keys[i] >> 2
            # the quadrants in scalars: an array here compiled numpy's allocation and
            # slice assignment into the first run (~0.2 s)
            q0 = q1 = q2 = q3 = np.int64(meta[EMPTY + lv])
            while i < n and keys[i] >> 2 == parent:
                q = keys[i] & 3
                if q == 0:
                    q0 = ids[i]
                elif q == 1:
                    q1 = ids[i]
                elif q == 2:
                    q2 = ids[i]
                else:
                    q3 = ids[i]
                i += 1
            node = join(q0, q1, q2, q3, np.int64(lv + 1), nodes, slots, meta)
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
