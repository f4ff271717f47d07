"""The store's upkeep: entering every entry into fresh hash indexes (after a table grew)
and garbage collection (when the memory limit stops the doubling), for either kind of leaf.
Their own module and kernel group: a run whose tables never fill (the README's Life runs)
does not compile them, and the first run that does fill announces them (a short notice).
"""

from __future__ import annotations

import numpy as np
from camlab88.apps.ca.hashlife.store import (
    EMPTY,
    EMPTY_LEAF,
    FULL,
    LEAF,
    LEVEL,
    N_LEAVES,
    N_NODES,
    RESJ,
    TABLES,
    TOP_LEVEL,
    WALL_AT,
    WALL_LEAF,
    leaf_hash,
    node_hash,
)
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__, sources=("camlab88.apps.ca.hashlife.store",))


NODE_TABLE, LEAF_TABLE = 1, 2  # rehash's ``which``: bits of the tables to enter anew


@kernels.export(f"void(int64, {TABLES})")
def rehash(which, nodes, slots, leaves, lslots, meta):
    """Enter every node (``which`` & NODE_TABLE) and every table leaf (& LEAF_TABLE), all
    distinct, into their empty hash indexes."""
    if which & NODE_TABLE:
        mask = np.uint64(slots.shape[0] - 1)
        for i in range(1, meta[N_NODES]):
            s = np.uint64(node_hash(nodes[i, 0], nodes[i, 1], nodes[i, 2], nodes[i, 3],
                                    nodes[i, LEVEL], mask))
            while slots[s] != 0:
                s = (s + np.uint64(1)) & mask
            slots[s] = i
    if which & LEAF_TABLE:
        mask = np.uint64(lslots.shape[0] - 1)
        for i in range(1, meta[N_LEAVES]):
            s = np.uint64(leaf_hash(leaves, i, 0, mask))
            while lslots[s] != 0:
                s = (s + np.uint64(1)) & mask
            lslots[s] = i


@kernels.export(f"int64(int64[::1], {TABLES})")
def collect(roots, nodes, slots, leaves, lslots, meta):
    """Keep only the nodes and leaves reachable from ``roots`` and the empty and wall
    towers (renumbered in the order they were made, so children stay before parents),
    forget every memoised result, rebuild both hashes; ``roots`` are rewritten with their
    new ids.  Value leaves are not entries: their ids stay."""
    n, m = meta[N_NODES], meta[N_LEAVES]
    low = meta[LEAF] + 1  # the level whose quadrants are leaves
    values = meta[LEAF] == 0
    keep = np.zeros(n, np.uint8)
    keep_leaf = np.zeros(m, np.uint8)
    if not values:
        keep_leaf[EMPTY_LEAF] = keep_leaf[WALL_LEAF] = 1
    stack = np.empty(4 * n + roots.shape[0] + 2 * TOP_LEVEL, np.int64)
    top = 0
    for r in range(roots.shape[0]):
        stack[top] = roots[r]
        top += 1
    for lv in range(low, TOP_LEVEL + 1):
        stack[top] = meta[EMPTY + lv]
        stack[top + 1] = meta[WALL_AT + lv]
        top += 2
    while top > 0:
        top -= 1
        i = stack[top]
        if keep[i]:
            continue
        keep[i] = 1
        for q in range(4):
            if nodes[i, LEVEL] != low:
                stack[top] = nodes[i, q]
                top += 1
            elif not values:
                keep_leaf[nodes[i, q]] = 1
    new_leaf = np.zeros(m, np.int64)
    k = 1
    for i in range(1, m):
        if keep_leaf[i]:
            new_leaf[i] = k
            for q in range(8):  # word by word: a row assignment compiles numpy's broadcasting
                leaves[k, q] = leaves[i, q]
            k += 1
    meta[N_LEAVES] = k
    new = np.zeros(n, np.int64)
    k = 1
    for i in range(1, n):
        if keep[i]:
            new[i] = k
            below = nodes[i, LEVEL] == low
            for q in range(4):
                c = nodes[i, q]
                if not below:
                    nodes[k, q] = new[c]
                elif values:
                    nodes[k, q] = c
                else:
                    nodes[k, q] = new_leaf[c]
            nodes[k, RESJ] = 0
            nodes[k, LEVEL] = nodes[i, LEVEL]
            nodes[k, FULL] = 0
            k += 1
    meta[N_NODES] = k
    slots[:] = 0
    lslots[:] = 0
    rehash(NODE_TABLE | LEAF_TABLE, nodes, slots, leaves, lslots, meta)
    for r in range(roots.shape[0]):
        roots[r] = new[roots[r]]
    for lv in range(low, TOP_LEVEL + 1):
        meta[EMPTY + lv] = new[meta[EMPTY + lv]]
        meta[WALL_AT + lv] = new[meta[WALL_AT + lv]]
    return k
