"""The memoised HashLife recursion, generalised to the rules' message reach.

A node of level k (2**k cells square) with 2**s >= the reach knows its centre (level k-1)
after 2**j generations for any j <= k - 2 - s: the light cone of 2**j generations at reach
r <= 2**s stays inside the 2**(k-2) margin.  At full speed (j = k - 2 - s) the nine
overlapping sub-squares advance 2**(j-1) and the four squares built from their results
advance 2**(j-1) more (Gosper 1984); below full speed the nine contribute their centres
unadvanced and the four advance 2**j.  Leaves (level ``base``) run the rules directly
(``leaf.generation``).  Every kernel returns -1 when the node table is full.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from apps.ca.hashlife.leaf import generation
from apps.ca.hashlife.store import join


@njit(cache=True)
def to_grid(node, level, g, y0, x0, ch, empty):
    """Write the cells of ``node`` into g[y0:, x0:]."""
    if level == 0:
        g[y0, x0] = node
        return
    side = np.int64(1) << level
    if node == empty[level]:
        g[y0:y0 + side, x0:x0 + side] = 0
        return
    h = side >> 1
    k = level - 1
    to_grid(np.int64(ch[node, 0]), k, g, y0, x0, ch, empty)
    to_grid(np.int64(ch[node, 1]), k, g, y0, x0 + h, ch, empty)
    to_grid(np.int64(ch[node, 2]), k, g, y0 + h, x0, ch, empty)
    to_grid(np.int64(ch[node, 3]), k, g, y0 + h, x0 + h, ch, empty)


@njit(cache=True)
def from_grid(g, y0, x0, level, ids, ch, lvl, slots, meta):
    """The node of the 2**level square g[y0:, x0:], built bottom-up in ``ids`` (scratch at
    least that square); -1 if the table is full."""
    side = np.int64(1) << level
    for y in range(side):
        for x in range(side):
            ids[y, x] = g[y0 + y, x0 + x]
    step = np.int64(1)
    while step < side:
        for y in range(0, side, 2 * step):
            for x in range(0, side, 2 * step):
                n = join(ids[y, x], ids[y, x + step], ids[y + step, x],
                         ids[y + step, x + step], ch, lvl, slots, meta)
                if n < 0:
                    return np.int64(-1)
                ids[y, x] = n
        step *= 2
    return np.int64(ids[0, 0])


@njit(cache=True)
def leaf_step(node, j, r, ch, lvl, slots, meta, empty, rule, grids):
    """Centre of leaf ``node`` after 2**j generations, by running the rules on its grid."""
    inc, mop, mval, lookup, kind, a, b, form = rule
    level = np.int64(lvl[node])
    n = np.int64(1) << level
    src, dst, ids = grids[0], grids[1], grids[2]
    to_grid(node, level, src, np.int64(0), np.int64(0), ch, empty)
    total = np.int64(1) << j
    for g in range(1, total + 1):
        lo = n // 4 - (total - g) * r  # only what the later generations still need
        generation(src, dst, lo, n - lo, inc, mop, mval, lookup, kind, a, b, form)
        src, dst = dst, src
    return from_grid(src, n // 4, n // 4, level - 1, ids, ch, lvl, slots, meta)


@njit(cache=True)
def _centre(n, ch, lvl, slots, meta):
    return join(np.int64(ch[ch[n, 0], 3]), np.int64(ch[ch[n, 1], 2]),
                np.int64(ch[ch[n, 2], 1]), np.int64(ch[ch[n, 3], 0]), ch, lvl, slots, meta)


@njit(cache=True)
def step(node, j, P, ch, lvl, res, resj, slots, meta, empty, rule, grids):
    """Centre of ``node`` after 2**j generations (j <= level - 2 - s); -1 if the table is
    full.  ``P`` = (leaf level, s, reach).  Self-recursive only: numba's cache reloads a
    mutually recursive pair wrongly (measured: a crash in the second process)."""
    if resj[node] == j:
        return np.int64(res[node])
    k = np.int64(lvl[node])
    if node == empty[k]:
        return np.int64(empty[k - 1])
    if k == P[0]:
        out = leaf_step(node, j, P[2], ch, lvl, slots, meta, empty, rule, grids)
        if out >= 0:
            res[node] = out
            resj[node] = j
        return out
    full = j == k - 2 - P[1]
    nine = _nine(node, ch, lvl, slots, meta)
    jj = j - 1 if full else j
    for i in range(9):
        if nine[i] < 0:
            return np.int64(-1)
        if full:
            nine[i] = step(nine[i], jj, P, ch, lvl, res, resj, slots, meta, empty, rule, grids)
        else:
            nine[i] = _centre(nine[i], ch, lvl, slots, meta)
        if nine[i] < 0:
            return np.int64(-1)
    four = np.empty(4, np.int64)
    for q in range(4):
        y, x = q // 2, q % 2
        m = join(nine[3 * y + x], nine[3 * y + x + 1], nine[3 * y + x + 3],
                 nine[3 * y + x + 4], ch, lvl, slots, meta)
        if m < 0:
            return np.int64(-1)
        four[q] = step(m, jj, P, ch, lvl, res, resj, slots, meta, empty, rule, grids)
        if four[q] < 0:
            return np.int64(-1)
    out = join(four[0], four[1], four[2], four[3], ch, lvl, slots, meta)
    if out >= 0:
        res[node] = out
        resj[node] = j
    return out


@njit(cache=True)
def _nine(node, ch, lvl, slots, meta):
    """The nine overlapping half-size squares of ``node``, row by row (-1: table full)."""
    a, b, c, d = ch[node, 0], ch[node, 1], ch[node, 2], ch[node, 3]
    nine = np.empty(9, np.int64)
    nine[0], nine[2], nine[6], nine[8] = a, b, c, d
    nine[1] = join(np.int64(ch[a, 1]), np.int64(ch[b, 0]), np.int64(ch[a, 3]),
                   np.int64(ch[b, 2]), ch, lvl, slots, meta)
    nine[3] = join(np.int64(ch[a, 2]), np.int64(ch[a, 3]), np.int64(ch[c, 0]),
                   np.int64(ch[c, 1]), ch, lvl, slots, meta)
    nine[4] = join(np.int64(ch[a, 3]), np.int64(ch[b, 2]), np.int64(ch[c, 1]),
                   np.int64(ch[d, 0]), ch, lvl, slots, meta)
    nine[5] = join(np.int64(ch[b, 2]), np.int64(ch[b, 3]), np.int64(ch[d, 0]),
                   np.int64(ch[d, 1]), ch, lvl, slots, meta)
    nine[7] = join(np.int64(ch[c, 1]), np.int64(ch[d, 0]), np.int64(ch[c, 3]),
                   np.int64(ch[d, 2]), ch, lvl, slots, meta)
    return nine
