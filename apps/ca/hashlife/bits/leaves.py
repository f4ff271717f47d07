"""The binary path's base case: a level-5 node (32 x 32 cells, four leaves) to its centre
leaf after up to 8 generations, by bit operations on two rows of 32 cells per uint64.

The scratch ``G`` (uint64, PLANES x 32): planes 0 and 1 hold the live cells of this and the
next generation, plane 2 the wall, in words 1..16 (word i: row 2i-2 in bits 0..31, row 2i-1
in bits 32..63, column x in bit x of its row), words 0 and 17 of planes 0 and 1 zero, so a
word's neighbours are read without a test (rows beyond the square read as dead: they only
reach rows no generation can know); plane 3 holds the centre leaf's words.  Shifting a word
by one column carries bit 31 of one row into column 0 of the other: harmless, as columns 0
and 31 are outside what generation 1 can know anyway, and that ignorance spreads a column a
generation like the light cone's.  Two kernels, both derived from the rules' 512 table
(rule.py): a bit-sliced adder for outer-totalistic rules, a 4 x 4 -> 2 x 2 lookup for the
others.  The wall is masked off after each generation: nothing is born in it and, holding
no live cells, it sends nothing; a plane with no wall yet (no bounded plane framed) skips it.
"""

from __future__ import annotations

import numpy as np
from camlab88.apps.ca.hashlife.bits.rule import KIND_TOTALISTIC, LUT, TERM, TERM_ANY, TERM_BIRTH
from camlab88.apps.ca.hashlife.store import HAS_WALL, all_tables, leaf
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__, sources=("camlab88.apps.ca.hashlife.store", "camlab88.base.raw_views",
                                         "camlab88.base.raw_view_intrinsics"))

LOW = np.uint64(0xFFFFFFFF)
HALF = np.uint64(0xFFFF)
ONES = np.uint64(0xFFFFFFFFFFFFFFFF)
U1, U16, U32 = np.uint64(1), np.uint64(16), np.uint64(32)
WALL, CENTRE = 2, 3  # the wall plane; the plane of the centre leaf's words
PLANES = 4  # of the scratch (run.py)


@kernels.kernel(inline="always")
def _pair(leaves, i, w, half):
    """Rows 2h, 2h+1 (h = 2w + half) of leaf i's word w as 16-bit pieces at bits 0 and 32."""
    x = leaves[np.uint64(i), w] >> np.uint64(32 * half)  # unsigned: no negative-index test
    return (x & HALF) | ((x & np.uint64(0xFFFF0000)) << U16)


@kernels.kernel(inline="always")
def load(nw, ne, sw, se, leaves, walls, G):
    """The 32 x 32 square of four leaves into plane 0 (live) and plane 2 (the wall, or none
    if ``walls`` is False)."""
    for plane in range(2 if walls else 1):
        for h in range(8):
            w, half = 4 * plane + (h >> 1), h & 1
            G[2 * plane, 1 + h] = _pair(leaves, nw, w, half) | \
                (_pair(leaves, ne, w, half) << U16)
            G[2 * plane, 9 + h] = _pair(leaves, sw, w, half) | \
                (_pair(leaves, se, w, half) << U16)
    if not walls:
        for i in range(1, 17):
            G[WALL, i] = np.uint64(0)
    G[0, 0] = G[0, 17] = G[1, 0] = G[1, 17] = np.uint64(0)


@kernels.kernel(inline="always")
def centre(p, G, leaves, lslots, meta):
    """The leaf of the centre 16 x 16 of plane ``p`` with the wall of plane 2 (zeros if
    there is none: ``load``); -1 if the leaf table is full."""
    for half in range(2):
        plane = p if half == 0 else WALL
        for w in range(4):
            a, b = G[plane, 5 + 2 * w], G[plane, 6 + 2 * w]
            G[CENTRE, 4 * half + w] = \
                ((a >> np.uint64(8)) & HALF) | (((a >> np.uint64(40)) & HALF) << U16) | \
                (((b >> np.uint64(8)) & HALF) << U32) | \
                (((b >> np.uint64(40)) & HALF) << np.uint64(48))
    return leaf(G, CENTRE, 0, leaves, lslots, meta)


@kernels.kernel(inline="always")
def _sum3(x):
    """Two bits of x << 1 + x + x >> 1 at each bit."""
    left, right = x << U1, x >> U1
    return left ^ x ^ right, (left & x) | (right & (left ^ x))


@kernels.kernel(inline="always")
def _term(R, j):
    """Term j's block-sum bits and masks (v0..v3, keep, flip); past the last term, one no
    block sum (at most 9) meets, so a pass of two terms serves any number."""
    if j >= np.int64(R[1]):
        return ONES, ONES, ONES, ONES, np.uint64(0), np.uint64(0)
    at = 2 + TERM * j
    kind = R[at]
    return (R[at + 1], R[at + 2], R[at + 3], R[at + 4],
            ONES if kind == TERM_ANY else np.uint64(0),  # else: births or survivals
            ONES if kind == TERM_BIRTH else np.uint64(0))


@kernels.kernel(inline="always")
def _hit(n0, n1, n2, n3, x, v0, v1, v2, v3, keep, flip):
    """Where the block sum n0..n3 is the term's and the centre x is of its kind."""
    return ~((n0 ^ v0) | (n1 ^ v1) | (n2 ^ v2) | (n3 ^ v3)) & (keep | (x ^ flip))


@kernels.kernel(inline="always")
def totalistic(s, d, pair, more, G):
    """Plane d = the next generation of plane s by a pair of terms (``_term``s, block sums:
    rule.totalistic_terms), OR-ed into plane d where ``more`` has bits (the pairs after the
    first).  One pass with no loop-carried values, no tests and no stores but plane d's,
    which LLVM vectorises (AVX-512 here): each word's rows' 3-sums and those of its two
    neighbours (recomputed: cheaper than storing them), the block sum's four bits, the two
    terms.  All 16 words are computed; later generations use only those they can know."""
    a0_, a1_, a2_, a3_, ak, af, b0_, b1_, b2_, b3_, bk, bf = pair
    for i in range(1, 17):
        x = G[s, i]
        p0, p1 = _sum3(G[s, i - 1])
        m0, m1 = _sum3(x)
        q0, q1 = _sum3(G[s, i + 1])
        # the rows above (2i-1, 2i) and below (2i+1, 2i+2) each word's two rows (0-based)
        a0, a1 = (m0 << U32) | (p0 >> U32), (m1 << U32) | (p1 >> U32)
        c0, c1 = (m0 >> U32) | (q0 << U32), (m1 >> U32) | (q1 << U32)
        k = (a0 & m0) | (c0 & (a0 ^ m0))  # a carry of 2
        t = a1 ^ m1 ^ c1
        u = (a1 & m1) | (c1 & (a1 ^ m1))  # a 4
        v = t & k  # another 4
        n0, n1, n2, n3 = a0 ^ m0 ^ c0, t ^ k, u ^ v, u & v
        hit = _hit(n0, n1, n2, n3, x, a0_, a1_, a2_, a3_, ak, af) | \
            _hit(n0, n1, n2, n3, x, b0_, b1_, b2_, b3_, bk, bf)
        G[d, i] = (hit | (G[d, i] & more)) & ~G[WALL, i]


@kernels.kernel(inline="always")
def lookup(s, d, lo, hi, R, G):
    """Plane d words lo..hi-1 = the next generation of plane s by R's 4 x 4 -> 2 x 2 table:
    each word's two rows from the four rows around them, two columns at a time (columns 0
    and 31, which generation 1 cannot know, are left dead)."""
    for i in range(lo, hi):
        r0 = G[s, i - 1] >> U32
        r1, r2 = G[s, i] & LOW, G[s, i] >> U32
        r3 = G[s, i + 1] & LOW
        top = np.uint64(0)
        bottom = np.uint64(0)
        for x in range(1, 31, 2):
            sh = np.uint64(x - 1)
            f = np.uint64(0xF)
            index = ((r0 >> sh) & f) | (((r1 >> sh) & f) << np.uint64(4)) | \
                (((r2 >> sh) & f) << np.uint64(8)) | (((r3 >> sh) & f) << np.uint64(12))
            o = R[LUT + np.int64(index)]
            top |= (o & np.uint64(3)) << np.uint64(x)
            bottom |= ((o >> np.uint64(2)) & np.uint64(3)) << np.uint64(x)
        G[d, i] = (top | (bottom << U32)) & ~G[WALL, i]


# A call, not IR-inlined into the recursion (where it was inlined twice): a cold first run
# of `ca run --engine hashlife` took 29 s of CPU instead of 42 with the same jump times
# (docs/perf/startup.md).  Without numba's runtime, like the recursion, so the call passes
# its arrays without atomic reference counts (the reason the inlining was measured faster).
# One copy of each kernel's pass (not one per kind of wall or of pair): a first compile's
# time grows with every inlined copy.
@kernels.kernel(_nrt=False)
def advance(node, gens, at):
    """The centre leaf of level-5 ``node`` after ``gens`` (0..8) generations; -1 if the
    leaf table is full.  ``at``: the address of the store's meta with the tables' addresses
    (store.publish)."""
    nodes, _, leaves, lslots, meta, R, G = all_tables(at)
    walls = meta[HAS_WALL] != 0  # no wall anywhere until a bounded plane was framed
    load(np.int64(nodes[node, 0]), np.int64(nodes[node, 1]), np.int64(nodes[node, 2]),
         np.int64(nodes[node, 3]), leaves, walls, G)
    s = np.int64(0)
    if R[0] == KIND_TOTALISTIC:
        # The first pair decoded once a base case, not once a generation (365 against
        # 245 ns a base case of 8 generations, with the passes' row sums kept in planes);
        # Life-like rules have one or two terms.
        first = _term(R, 0) + _term(R, 1)
        pairs = max(np.int64(R[1]), 1)
        for _ in range(gens):
            for j in range(0, pairs, 2):
                pair = first if j == 0 else _term(R, j) + _term(R, j + 1)
                totalistic(s, 1 - s, pair, ONES if j > 0 else np.uint64(0), G)
            s = 1 - s
    else:
        for g in range(1, gens + 1):
            lo = 5 - (gens - g + 1) // 2  # the words of rows 8-(gens-g) .. 23+(gens-g)
            lookup(s, 1 - s, lo, 18 - lo, R, G)
            s = 1 - s
    return centre(s, G, leaves, lslots, meta)
