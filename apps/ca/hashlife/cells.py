"""Cell lists to the plane's tree, for either kind of leaf: a sparse pattern's cells (no
dense window) into leaves and levels, and whether live cells lie near the wrapping plane's
seam.  Their own module and kernel group: a `ca run --json` of a small Life pattern (built
from its dense window) never compiles them; the first run that needs them announces them.
The way back, a plane's cells listed, is ``listing``."""

from __future__ import annotations

import numpy as np

from camlab88.apps.ca.hashlife.kernels import (
    PLANE_LEVEL,
    any_live,
    from_cells,
    morton,
)


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
