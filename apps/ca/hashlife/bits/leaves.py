"""The binary path's base case: a level-5 node (32 x 32 cells, four leaves) to its centre
leaf after up to 8 generations, by bit operations on two rows of 32 cells per uint64.

The scratch ``G`` (uint64, PLANES x 32): planes 0 and 1 hold the live cells of this and the next
generation, plane 2 the wall, in 16 words each (word i: row 2i in bits 0..31, row 2i+1 in
bits 32..63, column x in bit x of its row); plane 3 is work space.  Rows beyond the square
read as dead: they only reach rows that no generation can know.  Shifting a word by one column
carries bit 31 of one row into column 0 of the other: harmless, as columns 0 and 31 are
outside what generation 1 can know anyway, and that ignorance spreads a column a
generation like the light cone's.  Two kernels, both derived from the rules' 512 table
(rule.py): a bit-sliced adder for outer-totalistic rules, a 4 x 4 -> 2 x 2 lookup for the
others.  The wall is masked off after each generation: nothing is born in it and,
holding no live cells, it sends nothing.
"""

from __future__ import annotations

import numpy as np

from apps.ca.hashlife.bits.rule import KIND_TOTALISTIC, LUT, TERM, TERM_ANY, TERM_BIRTH
from apps.ca.hashlife.store import HAS_WALL, leaf
from base.kernel_set import KernelSet

kernels = KernelSet(__name__, sources=("apps.ca.hashlife.store",))

LOW = np.uint64(0xFFFFFFFF)
HALF = np.uint64(0xFFFF)
ONES = np.uint64(0xFFFFFFFFFFFFFFFF)
U1, U16, U32 = np.uint64(1), np.uint64(16), np.uint64(32)
SCRATCH, WORDS_AT = 3, 16  # plane 3: the lookup kernel's rows, from word 16 the leaf words
X0, X1 = 4, 5  # the totalistic kernel's planes of row sums
PLANES = 6  # of the scratch (run.py)


@kernels.kernel(inline="always")
def _pair(leaves, i, w, half):
    """Rows 2h, 2h+1 (h = 2w + half) of leaf i's word w as 16-bit pieces at bits 0 and 32."""
    x = leaves[i, w] >> np.uint64(32 * half)
    return (x & HALF) | ((x & np.uint64(0xFFFF0000)) << U16)


@kernels.kernel(inline="always")
def load(nw, ne, sw, se, leaves, meta, G):
    """The 32 x 32 square of four leaves into planes 0 (live) and 2 (wall)."""
    walls = meta[HAS_WALL] != 0  # no wall anywhere until a bounded plane was framed
    for plane in range(2 if walls else 1):
        for h in range(8):
            w, half = 4 * plane + (h >> 1), h & 1
            G[2 * plane, h] = _pair(leaves, nw, w, half) | (_pair(leaves, ne, w, half) << U16)
            G[2 * plane, 8 + h] = _pair(leaves, sw, w, half) | \
                (_pair(leaves, se, w, half) << U16)


@kernels.kernel(inline="always")
def centre(p, G, leaves, lslots, meta):
    """The leaf of the centre 16 x 16 of plane ``p`` (with the wall of plane 2); -1 if the
    leaf table is full."""
    for half in range(2):
        plane = p if half == 0 else 2
        for w in range(4):
            a, b = G[plane, 4 + 2 * w], G[plane, 5 + 2 * w]
            G[SCRATCH, WORDS_AT + 4 * half + w] = \
                ((a >> np.uint64(8)) & HALF) | (((a >> np.uint64(40)) & HALF) << U16) | \
                (((b >> np.uint64(8)) & HALF) << U32) | \
                (((b >> np.uint64(40)) & HALF) << np.uint64(48))
    return leaf(G, SCRATCH, WORDS_AT, leaves, lslots, meta)


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
def totalistic(s, d, R, G):
    """Plane d = the next generation of plane s by the terms of R (block sums,
    rule.totalistic_terms): the sum of each 3 x 3 block, centre included, by bit-sliced
    adders.  Two whole-plane passes with no loop-carried values and no inner loop, which
    LLVM vectorises (AVX-512 here): the rows' sums into planes X0/X1 (one word of padding
    each side), then per word the block sum's bits and two terms at a time, OR-ed into
    plane d (one pass for Life's two terms; 385 against 650 ns a base case of 8
    generations, when the terms were a loop over stored block-sum planes).  All 16 words
    are computed; later generations use only those they can know."""
    for i in range(16):
        x = G[s, i]
        left, right = x << U1, x >> U1
        G[X0, i + 1] = left ^ x ^ right
        G[X1, i + 1] = (left & x) | (right & (left ^ x))
    for j in range(0, max(np.int64(R[1]), 1), 2):
        a0_, a1_, a2_, a3_, ak, af = _term(R, j)
        b0_, b1_, b2_, b3_, bk, bf = _term(R, j + 1)
        more = ONES if j > 0 else np.uint64(0)  # the first pair writes, the others OR in
        for i in range(16):
            p0, p1 = G[X0, i], G[X1, i]
            m0, m1 = G[X0, i + 1], G[X1, i + 1]
            q0, q1 = G[X0, i + 2], G[X1, i + 2]
            # the rows above (2i-1, 2i) and below (2i+1, 2i+2) each word's two rows
            a0, a1 = (m0 << U32) | (p0 >> U32), (m1 << U32) | (p1 >> U32)
            c0, c1 = (m0 >> U32) | (q0 << U32), (m1 >> U32) | (q1 << U32)
            k = (a0 & m0) | (c0 & (a0 ^ m0))  # a carry of 2
            t = a1 ^ m1 ^ c1
            u = (a1 & m1) | (c1 & (a1 ^ m1))  # a 4
            v = t & k  # another 4
            n0, n1, n2, n3 = a0 ^ m0 ^ c0, t ^ k, u ^ v, u & v
            x = G[s, i]
            hit = _hit(n0, n1, n2, n3, x, a0_, a1_, a2_, a3_, ak, af) | \
                _hit(n0, n1, n2, n3, x, b0_, b1_, b2_, b3_, bk, bf)
            G[d, i] = ((G[d, i] & more) | hit) & ~G[2, i]


@kernels.kernel(inline="always")
def lookup(s, d, lo, hi, R, G):
    """Plane d words lo..hi-1 = the next generation of plane s by R's 4 x 4 -> 2 x 2 table:
    each word's two rows from the four rows around them, two columns at a time (columns 0
    and 31, which generation 1 cannot know, are left dead)."""
    for i in range(lo, hi):
        r0 = G[s, i - 1] >> U32 if i > 0 else np.uint64(0)
        r1, r2 = G[s, i] & LOW, G[s, i] >> U32
        r3 = G[s, i + 1] & LOW if i < 15 else np.uint64(0)
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
        G[d, i] = (top | (bottom << U32)) & ~G[2, i]


# A call, not IR-inlined into the recursion (where it was inlined twice): a cold first run
# of `ca run --engine hashlife` took 29 s of CPU instead of 42 with the same jump times
# (docs/perf/startup.md).  Without numba's runtime, like the recursion, so the call passes
# its arrays without atomic reference counts (the reason the inlining was measured faster).
@kernels.kernel(_nrt=False)
def advance(node, gens, nodes, slots, leaves, lslots, meta, R, G):
    """The centre leaf of level-5 ``node`` after ``gens`` (0..8) generations; -1 if the
    leaf table is full.  (The arguments are the recursion's; ``slots`` is not needed.)"""
    load(np.int64(nodes[node, 0]), np.int64(nodes[node, 1]), np.int64(nodes[node, 2]),
         np.int64(nodes[node, 3]), leaves, meta, G)
    s = np.int64(0)
    for g in range(1, gens + 1):
        lo = 4 - (gens - g + 1) // 2  # the words of rows 8-(gens-g) .. 23+(gens-g)
        if R[0] == KIND_TOTALISTIC:
            totalistic(s, 1 - s, R, G)
        else:
            lookup(s, 1 - s, lo, 16 - lo, R, G)
        s = 1 - s
    return centre(s, G, leaves, lslots, meta)
