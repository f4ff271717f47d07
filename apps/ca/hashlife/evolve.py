"""The memoised HashLife recursion, generalised to the rules' message reach.

A node of level k (2**k cells square) with 2**s >= the reach knows its centre (level k-1)
after 2**j generations for any j <= k - 2 - s: the light cone of 2**j generations at reach
r <= 2**s stays inside the 2**(k-2) margin.  At full speed (j = k - 2 - s) the nine
overlapping sub-squares advance 2**(j-1) and the four squares built from their results
advance 2**(j-1) more (Gosper 1984); below full speed the nine contribute their centres
unadvanced and the four advance 2**j.  Leaves (level ``base``) run the rules directly
(``leaf.generation``).  Every kernel returns -1 when the node table is full.

Written for numba's costs as measured: compiled without numba's runtime (``_nrt=False``:
nothing here allocates), so array arguments are not atomically reference counted per call
(on the binary path, bits/evolve.py, that was half the time of small jumps); the recursion
is self-recursive only (a cached mutually recursive pair crashed the next process), passes
few arrays, keeps the nine and four squares in scalars (no heap allocation per call) and
looks up memoised results before calling.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from apps.ca.hashlife.leaf import generation
from apps.ca.hashlife.store import LEVEL, RES, RESJ
from apps.ca.hashlife.store import join as _join_inline


@njit(cache=True, _nrt=False)
def join(a, b, c, d, nodes, slots, meta):
    """The store's join as a call, not IR-inlined at each of the recursion's ten-odd sites:
    the first compile of both recursions took 18 s of CPU instead of 29, with the same jump
    times in an A/B (docs/perf/startup.md).  Without numba's runtime, as the recursion."""
    return _join_inline(a, b, c, d, nodes, slots, meta)


@njit(cache=True, _nrt=False)
def to_grid(node, level, G, p, nodes):
    """Write the cells of ``node`` into plane ``p`` of G, splitting in place."""
    side = np.int64(1) << level
    G[p, 0, 0] = node
    half = side
    while half > 1:
        quarter = half >> 1
        for y in range(0, side, half):
            for x in range(0, side, half):
                n = G[p, y, x]
                G[p, y, x] = nodes[n, 0]
                G[p, y, x + quarter] = nodes[n, 1]
                G[p, y + quarter, x] = nodes[n, 2]
                G[p, y + quarter, x + quarter] = nodes[n, 3]
        half = quarter


@njit(cache=True, _nrt=False)
def from_grid(G, p, y0, x0, level, nodes, slots, meta):
    """The node of the 2**level square at (y0, x0) of plane ``p``, built bottom-up in
    plane 2; -1 if the table is full."""
    side = np.int64(1) << level
    for y in range(side):
        for x in range(side):
            G[2, y, x] = G[p, y0 + y, x0 + x]
    step = np.int64(1)
    while step < side:
        for y in range(0, side, 2 * step):
            for x in range(0, side, 2 * step):
                n = join(G[2, y, x], G[2, y, x + step], G[2, y + step, x],
                         G[2, y + step, x + step], nodes, slots, meta)
                if n < 0:
                    return np.int64(-1)
                G[2, y, x] = n
        step *= 2
    return np.int64(G[2, 0, 0])


@njit(cache=True, _nrt=False)
def leaf_step(node, j, r, nodes, slots, meta, R, G):
    """Centre of leaf ``node`` after 2**j generations, by running the rules on its grid
    (planes 0 and 1 of G in turn)."""
    level = np.int64(nodes[node, LEVEL])
    n = np.int64(1) << level
    to_grid(node, level, G, np.int64(0), nodes)
    total = np.int64(1) << j
    s = np.int64(0)
    for g in range(1, total + 1):
        lo = n // 4 - (total - g) * r  # only what the later generations still need
        generation(G, s, 1 - s, lo, n - lo, R)
        s = 1 - s
    return from_grid(G, s, n // 4, n // 4, level - 1, nodes, slots, meta)


@njit(cache=True, inline="always")
def _q(nodes, n, q):
    return np.int64(nodes[n, q])


@njit(cache=True, _nrt=False)
def _centre(n, nodes, slots, meta):
    """The centre half of ``n`` (no time passes); -1 if the table is full."""
    return join(_q(nodes, _q(nodes, n, 0), 3), _q(nodes, _q(nodes, n, 1), 2),
                _q(nodes, _q(nodes, n, 2), 1), _q(nodes, _q(nodes, n, 3), 0), nodes, slots,
                meta)


@njit(cache=True, inline="always")
def _memo(n, j, nodes):
    """The memoised result of ``n`` for 2**j generations, -2 if none (-1: n is -1)."""
    if n < 0:
        return n
    if nodes[n, RESJ] == j + 1:
        return np.int64(nodes[n, RES])
    return np.int64(-2)


@njit(cache=True, _nrt=False)
def step(node, j, P, nodes, slots, meta, empty, R, G):
    """Centre of ``node`` after 2**j generations (j <= level - 2 - s); -1 if the table is
    full.  ``P`` = (leaf level, s, reach)."""
    k = np.int64(nodes[node, LEVEL])
    if node == empty[k]:
        return np.int64(empty[k - 1])
    if k == P[0]:
        out = leaf_step(node, j, P[2], nodes, slots, meta, R, G)
    else:
        full = j == k - 2 - P[1]
        jj = j - 1 if full else j
        a, b, c, d = _q(nodes, node, 0), _q(nodes, node, 1), _q(nodes, node, 2), \
            _q(nodes, node, 3)
        nine = (a, join(_q(nodes, a, 1), _q(nodes, b, 0), _q(nodes, a, 3), _q(nodes, b, 2),
                        nodes, slots, meta),
                b, join(_q(nodes, a, 2), _q(nodes, a, 3), _q(nodes, c, 0), _q(nodes, c, 1),
                        nodes, slots, meta),
                join(_q(nodes, a, 3), _q(nodes, b, 2), _q(nodes, c, 1), _q(nodes, d, 0),
                     nodes, slots, meta),
                join(_q(nodes, b, 2), _q(nodes, b, 3), _q(nodes, d, 0), _q(nodes, d, 1),
                     nodes, slots, meta),
                c, join(_q(nodes, c, 1), _q(nodes, d, 0), _q(nodes, c, 3), _q(nodes, d, 2),
                        nodes, slots, meta),
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
                    v = step(n, jj, P, nodes, slots, meta, empty, R, G)
            else:
                v = _centre(n, nodes, slots, meta)
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
        four = (join(r00, r01, r10, r11, nodes, slots, meta),
                join(r01, r02, r11, r12, nodes, slots, meta),
                join(r10, r11, r20, r21, nodes, slots, meta),
                join(r11, r12, r21, r22, nodes, slots, meta))
        t0 = t1 = t2 = t3 = np.int64(-1)
        for i in range(4):
            n = four[i]
            if n < 0:
                return np.int64(-1)
            v = _memo(n, jj, nodes)
            if v == -2:
                v = step(n, jj, P, nodes, slots, meta, empty, R, G)
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
        out = join(t0, t1, t2, t3, nodes, slots, meta)
    if out >= 0:
        nodes[node, RES] = out
        nodes[node, RESJ] = j + 1
    return out


def advance(node: int, j: int, params: np.ndarray, store, rules: np.ndarray,
            grids: np.ndarray) -> int:
    """The centre of ``node`` after 2**j generations (-1: the table filled up)."""
    if store.nodes[node, RESJ] == j + 1:
        return int(store.nodes[node, RES])
    return int(step(np.int64(node), np.int64(j), params, store.nodes, store.slots,
                    store.meta, store.empty, rules, grids))
