"""Statistics of a plane read from its tree without listing its cells (a jump can leave a
billion of them): cells per life-form and the occupied rows and columns, for either kind of
leaf (the leaf level in the store's meta says which: 0, a value; else a bit leaf)."""

from __future__ import annotations

import numpy as np

from camlab88.apps.ca.hashlife.kernels import (
    MASK_LEVEL,
    PLANE_LEVEL,
    count,
    occupy,
)


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
