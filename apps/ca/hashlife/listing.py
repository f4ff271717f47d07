"""A plane's live cells listed, for either kind of leaf (pictures, cell queries, saved
states).  Its own module and kernel group: a `ca run` that prints only the census never
compiles it."""

from __future__ import annotations

import numpy as np

from camlab88.apps.ca.hashlife.kernels import (
    PLANE_LEVEL,
    listing,
)


def cells(node: int, store) -> tuple[np.ndarray, np.ndarray, np.ndarray]:  # a Store
    """(ys, xs, values) of the plane node's live cells, sorted row by row (by numpy: a
    sort inside a kernel compiles numba's quicksort, seconds of a first run)."""
    out = listing(np.int64(node), store.nodes, store.leaves, store.meta)
    out = out[np.argsort(out[:, 0] * (1 << PLANE_LEVEL) + out[:, 1])]
    return out[:, 0].copy(), out[:, 1].copy(), out[:, 2].copy()
