"""The binary path's memoised recursion (Gosper 1984) over 16 x 16 leaves.

A node of level k >= 5 knows its centre after 2**j generations for j <= k - 2.  At full
speed (j = k - 2) the nine overlapping sub-squares advance 2**(j-1) and the four squares
built from their results 2**(j-1) more; below full speed the nine give their centres
unadvanced and the four advance 2**j.  Level 5 (four leaves) is the base case
(leaves.base: up to 8 generations by bit operations).  Kernels return -1 when a table is
full.  As in the generic recursion (../evolve.py): self-recursive only, the nine and four
squares in scalars, memoised results looked up before calling.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from apps.ca.hashlife.bits.leaves import base
from apps.ca.hashlife.bits.store import EMPTY, LEAF_LEVEL, LEVEL, RES, RESJ, WALL, join

BASE = LEAF_LEVEL + 1


@njit(cache=True, inline="always")
def _q(nodes, n, q):
    return np.int64(nodes[n, q])


@njit(cache=True)
def _centre(n, nodes, slots, leaves, lslots, meta, R, G):
    """The centre half of ``n`` (no time passes); -1 if a table is full."""
    k = np.int64(nodes[n, LEVEL])
    if k == BASE:
        return base(n, np.int64(0), nodes, leaves, lslots, meta, R, G)
    return join(_q(nodes, _q(nodes, n, 0), 3), _q(nodes, _q(nodes, n, 1), 2),
                _q(nodes, _q(nodes, n, 2), 1), _q(nodes, _q(nodes, n, 3), 0), k - 1, nodes,
                slots, meta)


@njit(cache=True, inline="always")
def _memo(n, j, nodes):
    """The memoised result of ``n`` for 2**j generations, -2 if none (-1: n is -1)."""
    if n < 0:
        return n
    if nodes[n, RESJ] == j + 1:
        return np.int64(nodes[n, RES])
    return np.int64(-2)


@njit(cache=True)
def step(node, j, nodes, slots, leaves, lslots, meta, R, G):
    """Centre of ``node`` after 2**j generations (j <= level - 2); -1 if a table is full."""
    k = np.int64(nodes[node, LEVEL])
    if node == meta[EMPTY + k]:
        return np.int64(meta[EMPTY + k - 1])
    if node == meta[WALL + k]:
        return np.int64(meta[WALL + k - 1])
    if k == BASE:
        out = base(node, np.int64(1) << j, nodes, leaves, lslots, meta, R, G)
    else:
        full = j == k - 2
        jj = j - 1 if full else j
        h = k - 1
        a, b, c, d = _q(nodes, node, 0), _q(nodes, node, 1), _q(nodes, node, 2), \
            _q(nodes, node, 3)
        nine = (a, join(_q(nodes, a, 1), _q(nodes, b, 0), _q(nodes, a, 3), _q(nodes, b, 2),
                        h, nodes, slots, meta),
                b, join(_q(nodes, a, 2), _q(nodes, a, 3), _q(nodes, c, 0), _q(nodes, c, 1),
                        h, nodes, slots, meta),
                join(_q(nodes, a, 3), _q(nodes, b, 2), _q(nodes, c, 1), _q(nodes, d, 0),
                     h, nodes, slots, meta),
                join(_q(nodes, b, 2), _q(nodes, b, 3), _q(nodes, d, 0), _q(nodes, d, 1),
                     h, nodes, slots, meta),
                c, join(_q(nodes, c, 1), _q(nodes, d, 0), _q(nodes, c, 3), _q(nodes, d, 2),
                        h, nodes, slots, meta),
                d)
        # the order above: r00, r01, r02, r10, r11, r12, r20, r21, r22 (row by row)
        r00 = r01 = r02 = r10 = r11 = r12 = r20 = r21 = r22 = np.int64(-1)
        for i in range(9):
            n = nine[i]
            if n < 0:
                return np.int64(-1)
            if full:
                v = _memo(n, jj, nodes)
                if v == -2:
                    v = step(n, jj, nodes, slots, leaves, lslots, meta, R, G)
            else:
                v = _centre(n, nodes, slots, leaves, lslots, meta, R, G)
            if v < 0:
                return np.int64(-1)
            if i == 0:
                r00 = v
            elif i == 1:
                r01 = v
            elif i == 2:
                r02 = v
            elif i == 3:
                r10 = v
            elif i == 4:
                r11 = v
            elif i == 5:
                r12 = v
            elif i == 6:
                r20 = v
            elif i == 7:
                r21 = v
            else:
                r22 = v
        four = (join(r00, r01, r10, r11, h, nodes, slots, meta),
                join(r01, r02, r11, r12, h, nodes, slots, meta),
                join(r10, r11, r20, r21, h, nodes, slots, meta),
                join(r11, r12, r21, r22, h, nodes, slots, meta))
        t0 = t1 = t2 = t3 = np.int64(-1)
        for i in range(4):
            n = four[i]
            if n < 0:
                return np.int64(-1)
            v = _memo(n, jj, nodes)
            if v == -2:
                v = step(n, jj, nodes, slots, leaves, lslots, meta, R, G)
            if v < 0:
                return np.int64(-1)
            if i == 0:
                t0 = v
            elif i == 1:
                t1 = v
            elif i == 2:
                t2 = v
            else:
                t3 = v
        out = join(t0, t1, t2, t3, h, nodes, slots, meta)
    if out >= 0:
        nodes[node, RES] = out
        nodes[node, RESJ] = j + 1
    return out


def advance(node: int, j: int, store, R: np.ndarray, G: np.ndarray) -> int:  # noqa: ANN001
    """The centre of ``node`` after 2**j generations (-1: a table filled up)."""
    if store.nodes[node, RESJ] == j + 1:
        return int(store.nodes[node, RES])
    return int(step(np.int64(node), np.int64(j), store.nodes, store.slots, store.leaves,
                    store.lslots, store.meta, R, G))
