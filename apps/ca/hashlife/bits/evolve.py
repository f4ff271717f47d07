"""The binary path's memoised recursion (Gosper 1984) over 16 x 16 leaves.

A node of level k >= 5 knows its centre after T generations for any T <= 2**(k-2): the
four squares built from the nine overlapping sub-squares' results advance
t2 = min(T, 2**(k-3)) generations, the nine the rest, T - t2 (none: their centres as they
are).  At full speed (T = 2**(k-2)) that is Gosper's; any other T costs one pass too, where
jumps of powers of two would take one pass per binary digit.  The memo keeps one T per
node.  Level 5 (four leaves) is the base case (leaves.base: up to 8 generations by bit
operations).  Kernels return -1 when a table is
full.  As in the generic recursion (../evolve.py): self-recursive only, the nine and four
squares in scalars, memoised results looked up before calling.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from apps.ca.hashlife.bits.leaves import base
from apps.ca.hashlife.bits.store import EMPTY, FULL, LEAF_LEVEL, LEVEL, RES, RESJ, WALL
from apps.ca.hashlife.bits.store import join as _join_inline

BASE = LEAF_LEVEL + 1


@njit(cache=True, _nrt=False)
def join(a, b, c, d, level, nodes, slots, meta):
    """The store's join as a call, not IR-inlined at each of the recursion's ten-odd sites:
    the first compile of both recursions took 18 s of CPU instead of 29, with the same jump
    times in an A/B (docs/perf/startup.md).  Without numba's runtime, as the recursion."""
    return _join_inline(a, b, c, d, level, nodes, slots, meta)


@njit(cache=True, inline="always")
def _q(nodes, n, q):
    return np.int64(nodes[n, q])


@njit(cache=True, inline="always")
def _centre(n, nodes, slots, leaves, lslots, meta, R, G):
    """The centre half of ``n`` (no time passes); -1 if a table is full."""
    k = np.int64(nodes[n, LEVEL])
    if k == BASE:
        return base(n, np.int64(0), nodes, leaves, lslots, meta, R, G)
    return join(_q(nodes, _q(nodes, n, 0), 3), _q(nodes, _q(nodes, n, 1), 2),
                _q(nodes, _q(nodes, n, 2), 1), _q(nodes, _q(nodes, n, 3), 0), k - 1, nodes,
                slots, meta)


@njit(cache=True, inline="always")
def _known(n, T, level, nodes, meta):
    """The result of ``n`` (of ``level``) for T generations if it is known without
    recursing — an empty or wall node's, or memoised — else -2 (-1: n is -1)."""
    if n < 0:
        return n
    if n == meta[EMPTY + level]:
        return meta[EMPTY + level - 1]
    if n == meta[WALL + level]:
        return meta[WALL + level - 1]
    if T == np.int64(1) << (level - 2):
        if nodes[n, FULL] > 0:
            return np.int64(nodes[n, FULL])
    elif nodes[n, RESJ] == T + 1:
        return np.int64(nodes[n, RES])
    return np.int64(-2)


# _nrt=False: the recursion allocates nothing, and without numba's runtime its array
# arguments are not reference counted — perf showed those atomic counts taking half the time
# of small jumps (gun 1.6 -> 0.7 ms, spacefiller 1.7 -> 0.8, puffer 95 -> 77).
@njit(cache=True, _nrt=False)
def step(node, T, nodes, slots, leaves, lslots, meta, R, G):
    """Centre of ``node`` after T generations (1 <= T <= 2**(level - 2)); -1 if a table is
    full.  The caller has looked for a known result first (``_known``)."""
    k = np.int64(nodes[node, LEVEL])
    if k == BASE:
        out = base(node, T, nodes, leaves, lslots, meta, R, G)
    else:
        h = k - 1
        t2 = min(T, np.int64(1) << (k - 3))  # the four's share: full speed if it can
        t1 = T - t2  # the nine's (0: their centres as they are)
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
            if t1 > 0:
                v = _known(n, t1, h, nodes, meta)
                if v == -2:
                    v = step(n, t1, nodes, slots, leaves, lslots, meta, R, G)
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
        u0 = u1 = u2 = u3 = np.int64(-1)
        for i in range(4):
            n = four[i]
            if n < 0:
                return np.int64(-1)
            v = _known(n, t2, h, nodes, meta)
            if v == -2:
                v = step(n, t2, nodes, slots, leaves, lslots, meta, R, G)
            if v < 0:
                return np.int64(-1)
            if i == 0:
                u0 = v
            elif i == 1:
                u1 = v
            elif i == 2:
                u2 = v
            else:
                u3 = v
        out = join(u0, u1, u2, u3, h, nodes, slots, meta)
    if out >= 0 and T == np.int64(1) << (k - 2):
        nodes[node, FULL] = out
    elif out >= 0:
        nodes[node, RES] = out
        nodes[node, RESJ] = T + 1
    return out


def advance(node: int, T: int, store, R: np.ndarray, G: np.ndarray) -> int:
    """The centre of ``node`` after T generations (-1: a table filled up)."""
    known = int(_known(np.int64(node), np.int64(T), np.int64(store.nodes[node, LEVEL]),
                       store.nodes, store.meta))
    if known != -2:
        return known
    return int(step(np.int64(node), np.int64(T), store.nodes, store.slots, store.leaves,
                    store.lslots, store.meta, R, G))
