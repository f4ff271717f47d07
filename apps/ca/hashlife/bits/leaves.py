"""The binary path's base case: a level-5 node (32 x 32 cells, four leaves) to its centre
leaf after up to 8 generations, advanced a row of 32 cells at a time with bit operations.

The scratch ``G`` (uint64, 4 x 32) holds the rows: planes 0 and 1 the live cells of this and
the next generation (column x in bit x), plane 2 the wall, plane 3 the words of the leaf
being made.  Generation g is only computed in rows and columns g..31-g, all that the
later generations still need.  Two kernels, both derived from the rules' 512 table
(rule.py): a bit-sliced adder of the eight neighbours for outer-totalistic rules, and a
4 x 4 -> 2 x 2 lookup for the others; the wall is masked off after each generation, so
nothing is born in it (and, holding no live cells, it sends nothing).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from apps.ca.hashlife.bits.rule import KIND_TOTALISTIC, LUT, TERM_ANY, TERM_BIRTH
from apps.ca.hashlife.bits.store import leaf

ROW_MASK = np.uint64(0xFFFFFFFF)
HALF = np.uint64(0xFFFF)
ONES = np.uint64(0xFFFFFFFFFFFFFFFF)


@njit(cache=True, inline="always")
def _leaf_row(leaves, i, plane, y):
    """Row y (16 bits) of leaf i's live cells (plane 0) or wall (plane 1)."""
    return (leaves[i, 4 * plane + (y >> 2)] >> np.uint64(16 * (y & 3))) & HALF


@njit(cache=True)
def load(nw, ne, sw, se, leaves, G):
    """Rows of the 32 x 32 square of four leaves into planes 0 (live) and 2 (wall)."""
    for plane in range(2):
        for y in range(16):
            G[2 * plane, y] = _leaf_row(leaves, nw, plane, y) | \
                (_leaf_row(leaves, ne, plane, y) << np.uint64(16))
            G[2 * plane, 16 + y] = _leaf_row(leaves, sw, plane, y) | \
                (_leaf_row(leaves, se, plane, y) << np.uint64(16))


@njit(cache=True)
def centre(p, G, leaves, lslots, meta):
    """The leaf of the centre 16 x 16 of plane ``p`` (with the wall of plane 2); -1 if the
    leaf table is full."""
    for w in range(8):
        G[3, w] = 0
    for y in range(16):
        shift = np.uint64(16 * (y & 3))
        G[3, y >> 2] |= ((G[p, 8 + y] >> np.uint64(8)) & HALF) << shift
        G[3, 4 + (y >> 2)] |= ((G[2, 8 + y] >> np.uint64(8)) & HALF) << shift
    return leaf(G[3], leaves, lslots, meta)


@njit(cache=True, inline="always")
def _eq(n0, n1, n2, n3, count):
    """Bits where the 4-bit sum n3 n2 n1 n0 equals ``count``."""
    m0 = ONES if count & 1 else np.uint64(0)
    m1 = ONES if count & 2 else np.uint64(0)
    m2 = ONES if count & 4 else np.uint64(0)
    m3 = ONES if count & 8 else np.uint64(0)
    return ~((n0 ^ m0) | (n1 ^ m1) | (n2 ^ m2) | (n3 ^ m3))


@njit(cache=True)
def totalistic(s, d, lo, hi, R, G):
    """Plane d rows lo..hi-1 = the next generation of plane s by the count terms of R."""
    terms = np.int64(R[1])
    for y in range(lo, hi):
        a, b, c = G[s, y - 1], G[s, y], G[s, y + 1]
        al, ar, cl, cr = a << np.uint64(1), a >> np.uint64(1), c << np.uint64(1), \
            c >> np.uint64(1)
        bl, br = b << np.uint64(1), b >> np.uint64(1)
        sa0 = al ^ a ^ ar
        sa1 = (al & a) | (ar & (al ^ a))
        sc0 = cl ^ c ^ cr
        sc1 = (cl & c) | (cr & (cl ^ c))
        sb0 = bl ^ br
        sb1 = bl & br
        n0 = sa0 ^ sb0 ^ sc0
        k0 = (sa0 & sb0) | (sc0 & (sa0 ^ sb0))  # carry into the 2s
        t = sa1 ^ sb1 ^ sc1
        u = (sa1 & sb1) | (sc1 & (sa1 ^ sb1))  # a 4
        n1 = t ^ k0
        v = t & k0  # another 4
        n2 = u ^ v
        n3 = u & v
        out = np.uint64(0)
        for i in range(terms):
            kind, count = R[2 + 2 * i], R[3 + 2 * i]
            e = _eq(n0, n1, n2, n3, count)
            if kind == TERM_ANY:
                out |= e
            elif kind == TERM_BIRTH:
                out |= e & ~b
            else:
                out |= e & b
        G[d, y] = out & ~G[2, y] & ROW_MASK


@njit(cache=True)
def lookup(s, d, lo, hi, R, G):
    """Plane d rows lo..hi-1 = the next generation of plane s by R's 4 x 4 -> 2 x 2 table
    (the columns and rows lo..hi-1 are an even number)."""
    for y in range(lo, hi, 2):
        r0, r1, r2, r3 = G[s, y - 1], G[s, y], G[s, y + 1], G[s, y + 2]
        top = np.uint64(0)
        bottom = np.uint64(0)
        for x in range(lo, hi, 2):
            sh = np.uint64(x - 1)
            f = np.uint64(0xF)
            index = ((r0 >> sh) & f) | (((r1 >> sh) & f) << np.uint64(4)) | \
                (((r2 >> sh) & f) << np.uint64(8)) | (((r3 >> sh) & f) << np.uint64(12))
            o = np.uint64(R[LUT + np.int64(index)])
            top |= (o & np.uint64(3)) << np.uint64(x)
            bottom |= ((o >> np.uint64(2)) & np.uint64(3)) << np.uint64(x)
        G[d, y] = top & ~G[2, y]
        G[d, y + 1] = bottom & ~G[2, y + 1]


@njit(cache=True)
def base(node, gens, nodes, leaves, lslots, meta, R, G):
    """The centre leaf of level-5 ``node`` after ``gens`` (0..8) generations; -1 if the
    leaf table is full."""
    load(np.int64(nodes[node, 0]), np.int64(nodes[node, 1]), np.int64(nodes[node, 2]),
         np.int64(nodes[node, 3]), leaves, G)
    s = np.int64(0)
    for g in range(1, gens + 1):
        lo = 8 - (gens - g)  # only what the later generations still need
        if R[0] == KIND_TOTALISTIC:
            totalistic(s, 1 - s, lo, 32 - lo, R, G)
        else:
            lookup(s, 1 - s, lo, 32 - lo, R, G)
        s = 1 - s
    return centre(s, G, leaves, lslots, meta)
