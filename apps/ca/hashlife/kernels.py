"""Every compiled kernel of HashLife, in one module: numba's cache checks a cached kernel
against its own source file only, and these kernels call each other (the recursion its leaf
kernels, every conversion the store's ``join`` and ``leaf``) and read each other's
constants, so one file is what makes that check right by construction (an edit of a callee
in another file once let a warm cache run an old recursion: a double free).  The Python
around them lives in the modules named after what they do (``store``, ``evolve``, ``leaf``,
``cells``, ...), which import what they call from here; their docstrings say how each
part works.  Kernel groups for the compile notice: apps/ca/hashlife/__init__.py.

Kernels run with one set of argument types each (docs/development.md, "numba's cache"):
Python callers cast with ``np.int64`` and pass C-contiguous arrays of the store's types.
"""

from __future__ import annotations

from types import FunctionType
from typing import Any

import numpy as np
from numba import njit

# ---- the store's layout (store.py) ----
TOP_LEVEL = 17  # the 65536-square plane is level 16; stepping frames it in a level-17 node
PLANE_LEVEL = 16
RES, RESJ, LEVEL, FULL = 4, 5, 6, 7  # node row columns after the four quadrants
ROW = 8
WALL = 65536  # the wall cell of value leaves: never changes, sends nothing
BIT_LEAF_LEVEL = 4
EMPTY_LEAF, WALL_LEAF = 1, 2  # of bit leaves
# meta: node and leaf counts; the leaf level, the base case's level, s (2**s >= the rules'
# reach) and the reach; whether any leaf has a wall yet (a bounded plane was framed; until
# then the bit kernels skip it); the ids of the empty and the wall node of each level.
N_NODES, N_LEAVES, LEAF, BASE, SHIFT, REACH, HAS_WALL = range(7)
EMPTY = 7
WALL_AT = EMPTY + TOP_LEVEL + 1
META = WALL_AT + TOP_LEVEL + 1
# Then one frame per level for the recursion's nine and four squares and their results
# (a level's call only calls the level below, so one frame a level suffices).
FRAMES, FRAME = META, 32
META_SIZE = FRAMES + FRAME * (TOP_LEVEL + 1)

# ---- the packed rules of value leaves (leaf.py) ----
LOOKUP_SIZE = 1 << 16  # the interpretation lookup's entries (apps/ca/tables.py's; a test)
M32 = 0xFFFFFFFF
H_TYPES, H_LINES, H_RY, H_RX, H_START, H_DY, H_DX, H_OP, H_VAL, H_LOOKUP, H_KIND, H_A, H_B, \
    H_FORM = range(14)
HEADER = 16

# ---- the binary rules' table (bits/rule.py) and the bit leaves' scratch ----
# kind, number of terms, each term (kind, then the four bits of its block sum as all-0 or
# all-1 masks, so the kernel compares by XOR), then the lookup.
KIND_TOTALISTIC, KIND_LOOKUP = 0, 1
TERM_ANY, TERM_BIRTH, TERM_SURVIVAL = 0, 1, 2
TERM = 5  # words per term
LUT = 64
WALL_PLANE, CENTRE_PLANE = 2, 3  # the wall plane; the plane of the centre leaf's words
PLANES = 4  # of the scratch
LOW = np.uint64(0xFFFFFFFF)
HALF = np.uint64(0xFFFF)
ONES = np.uint64(0xFFFFFFFFFFFFFFFF)
U1, U16, U32 = np.uint64(1), np.uint64(16), np.uint64(32)

# ---- the census (census.py), the upkeep ----
MASK_LEVEL = 6  # nodes of 64 cells square keep their row / column occupancy in one uint64
NODE_TABLE, LEAF_TABLE = 1, 2  # rehash's ``which``: bits of the tables to enter anew
# Odd multipliers of the leaf hash's eight words (splitmix, xxhash, murmur constants).
_LEAF_K = (0x9E3779B97F4A7C15, 0xC2B2AE3D27D4EB4F, 0x165667B19E3779F9, 0x85EBCA77C2B2AE63,
           0x27D4EB2F165667C5, 0xFF51AFD7ED558CCD, 0xC4CEB9FE1A85EC53, 0xD6E8FEB86659FD93)


# ---- the kernels: the store's, the rules', the bit leaves', the value leaves', the tree's
# levels, the census, the cell lists, the dense window, the listing, the upkeep, the
# recursion ----


@njit(cache=True, inline="always")
def _hash4(a, b, c, d, mask):
    h = (np.uint64(a) * np.uint64(0x9E3779B97F4A7C15)
         ^ np.uint64(b) * np.uint64(0xC2B2AE3D27D4EB4F)
         ^ np.uint64(c) * np.uint64(0x165667B19E3779F9)
         ^ np.uint64(d) * np.uint64(0x85EBCA77C2B2AE63))
    return np.int64((h ^ (h >> np.uint64(29))) & np.uint64(mask))


@njit(cache=True, inline="always")
def node_hash(a, b, c, d, level, mask):
    return _hash4(a, b, c, np.int64(d) ^ (np.int64(level) << 27), mask)


@njit(cache=True, inline="always")
def _mix(h):
    h = (h ^ (h >> np.uint64(31))) * np.uint64(0x7FB5D329728EA185)
    return h ^ (h >> np.uint64(27))


@njit(cache=True, inline="always")
def leaf_hash(W, r, at, mask):
    # eight independent multiplies, one mixing at the end: eight mixing rounds chained one
    # after another were ~10 ns more a base case (a leaf looked up each)
    h = (W[r, at] * np.uint64(_LEAF_K[0]) + W[r, at + 1] * np.uint64(_LEAF_K[1])
         + W[r, at + 2] * np.uint64(_LEAF_K[2]) + W[r, at + 3] * np.uint64(_LEAF_K[3])
         + W[r, at + 4] * np.uint64(_LEAF_K[4]) + W[r, at + 5] * np.uint64(_LEAF_K[5])
         + W[r, at + 6] * np.uint64(_LEAF_K[6]) + W[r, at + 7] * np.uint64(_LEAF_K[7]))
    return np.int64(_mix(h) & np.uint64(mask))


@njit(cache=True, inline="always")
def _join(a, b, c, d, level, nodes, slots, meta):
    # Slots and rows indexed by unsigned values: numba adds a test for negative indices
    # (Python's wrap-around) to every signed one, on the hash look-up's critical path.
    mask = np.uint64(slots.shape[0] - 1)
    s = np.uint64(node_hash(a, b, c, d, level, mask))
    while True:
        i = np.uint64(np.uint32(slots[s]))
        if i == 0:
            break
        if (nodes[i, 0] == a and nodes[i, 1] == b and nodes[i, 2] == c and nodes[i, 3] == d
                and nodes[i, LEVEL] == level):
            return np.int64(i)
        s = (s + np.uint64(1)) & mask
    n = meta[N_NODES]
    if n >= nodes.shape[0]:
        return np.int64(-1)
    slots[s] = n
    u = np.uint64(n)
    nodes[u, 0] = a
    nodes[u, 1] = b
    nodes[u, 2] = c
    nodes[u, 3] = d
    nodes[u, RESJ] = 0
    nodes[u, LEVEL] = level
    nodes[u, FULL] = 0
    meta[N_NODES] = n + 1
    return np.int64(n)


# A call, not IR-inlined at each of the recursion's ten-odd sites: the first compile of the
# recursion took 18 s of CPU instead of 29, with the same jump times in an A/B
# (docs/perf/startup.md).  Without numba's runtime, as the recursion.
@njit(cache=True, _nrt=False)
def join(a, b, c, d, level, nodes, slots, meta):
    """The node of ``level`` with quadrants a, b, c, d (nw, ne, sw, se), made at most
    once; -1 if the table is full."""
    return _join(a, b, c, d, level, nodes, slots, meta)


@njit(cache=True, inline="always")
def leaf(W, r, at, leaves, lslots, meta):
    """The id of the bit leaf with words W[r, at:at+8], made at most once; -1 if full.
    (Row and offset rather than a slice, and inlined: every array handed to a call is
    reference counted with atomic operations, measured at half the time of small jumps.)"""
    mask = np.uint64(lslots.shape[0] - 1)
    s = np.uint64(leaf_hash(W, r, at, mask))  # unsigned indices, as in _join
    while True:
        i = np.uint64(np.uint32(lslots[s]))
        if i == 0:
            break
        same = True
        for q in range(8):
            if leaves[i, q] != W[r, at + q]:
                same = False
                break
        if same:
            return np.int64(i)
        s = (s + np.uint64(1)) & mask
    n = meta[N_LEAVES]
    if n >= leaves.shape[0]:
        return np.int64(-1)
    lslots[s] = n
    u = np.uint64(n)
    for q in range(8):
        leaves[u, q] = W[r, at + q]
    meta[N_LEAVES] = n + 1
    return np.int64(n)


@njit(cache=True)
def towers(words, nodes, slots, leaves, lslots, meta):
    """The empty and the all-wall leaf (values 0 and WALL; or bit leaves 1 and 2, the rows
    of ``words``) and the uniform nodes of every level above them, into meta (one call: 26
    calls from Python cost 0.1 ms a store)."""
    low = meta[LEAF]
    for which in range(2):
        base = EMPTY if which == 0 else WALL_AT
        if low == 0:
            meta[base] = 0 if which == 0 else WALL
        else:
            if leaf(words, which, 0, leaves, lslots, meta) != EMPTY_LEAF + which:
                return -1
            meta[base + low] = EMPTY_LEAF + which
        for k in range(low + 1, TOP_LEVEL + 1):
            q = meta[base + k - 1]
            n = _join(q, q, q, q, np.int64(k), nodes, slots, meta)
            if n < 0:
                return -1
            meta[base + k] = n
    return 0








M32 = 0xFFFFFFFF


HEADER = 16


@njit(cache=True, inline="always")
def _apply(cur, op, val):
    if op == 1:
        return (cur + val) & M32
    if op == 2:
        return cur | val
    if op == 3:
        return cur & val
    return cur ^ val


@njit(cache=True)
def _interpret(v, R):
    """The life-form a cell with message value ``v`` becomes (0: dies)."""
    if v < LOOKUP_SIZE:
        i = R[R[H_LOOKUP] + v]
    else:
        i = -1
        kind, a, b = R[H_KIND], R[H_A], R[H_B]
        for j in range(R[H_LINES]):
            k = R[kind + j]
            if k == 0:
                hit = v == R[a + j]
            elif k == 1:
                hit = (v & R[a + j]) == R[b + j]
            else:
                hit = R[a + j] <= v <= R[b + j]
            if hit:
                i = j
                break
    return np.int64(0) if i < 0 else R[R[H_FORM] + i]


@njit(cache=True)
def generation(G, s, d, lo, hi, R):
    """Plane d = the next values of plane s for lo <= y, x < hi (the caller keeps the reach
    of every such cell inside the grid); plane 3 is the message scratch.  G holds four
    square planes one above the other (plane p, row y: G[p * side + y]; planes of one
    array, not views: numba reference-counts every view)."""
    n = G.shape[1]
    S, D, M = s * n, d * n, 3 * n
    ntypes, ry, rx = R[H_TYPES], R[H_RY], R[H_RX]
    start, sdy, sdx, sop, sval = R[H_START], R[H_DY], R[H_DX], R[H_OP], R[H_VAL]
    for y in range(lo, hi):
        for x in range(lo, hi):
            G[M + y, x] = -1  # -1: received nothing (message values are 32-bit, >= 0)
    for y in range(lo - ry, hi + ry):
        for x in range(lo - rx, hi + rx):
            t = G[S + y, x]
            if t <= 0 or t >= ntypes:
                continue
            for k in range(R[start + t], R[start + t + 1]):
                ty = y + R[sdy + k]
                tx = x + R[sdx + k]
                if lo <= ty < hi and lo <= tx < hi:
                    cur = G[M + ty, tx]
                    G[M + ty, tx] = _apply(cur if cur >= 0 else np.int64(0), R[sop + k],
                                          R[sval + k])
    for y in range(lo, hi):
        for x in range(lo, hi):
            v = G[M + y, x]
            if G[S + y, x] == WALL:
                G[D + y, x] = WALL
            elif v < 0:
                G[D + y, x] = 0
            else:
                G[D + y, x] = _interpret(v, R)


LOW = np.uint64(0xFFFFFFFF)


HALF = np.uint64(0xFFFF)


ONES = np.uint64(0xFFFFFFFFFFFFFFFF)


# ---- the bit leaves' base case ----
# The binary path's base case: a level-5 node (32 x 32 cells, four leaves) to its centre
# leaf after up to 8 generations, by bit operations on two rows of 32 cells per uint64.
#
# The scratch ``G`` (uint64, PLANES x 32): planes 0 and 1 hold the live cells of this and the
# next generation, plane 2 the wall, in words 1..16 (word i: row 2i-2 in bits 0..31, row 2i-1
# in bits 32..63, column x in bit x of its row), words 0 and 17 of planes 0 and 1 zero, so a
# word's neighbours are read without a test (rows beyond the square read as dead: they only
# reach rows no generation can know); plane 3 holds the centre leaf's words.  Shifting a word
# by one column carries bit 31 of one row into column 0 of the other: harmless, as columns 0
# and 31 are outside what generation 1 can know anyway, and that ignorance spreads a column a
# generation like the light cone's.  Two kernels, both derived from the rules' 512 table
# (bits/rule.py): a bit-sliced adder for outer-totalistic rules, a 4 x 4 -> 2 x 2 lookup for the
# others.  The wall is masked off after each generation: nothing is born in it and, holding
# no live cells, it sends nothing; a plane with no wall yet (no bounded plane framed) skips it.
@njit(cache=True, inline="always")
def _pair(leaves, i, w, half):
    """Rows 2h, 2h+1 (h = 2w + half) of leaf i's word w as 16-bit pieces at bits 0 and 32."""
    x = leaves[np.uint64(i), w] >> np.uint64(32 * half)  # unsigned: no negative-index test
    return (x & HALF) | ((x & np.uint64(0xFFFF0000)) << U16)


@njit(cache=True, inline="always")
def load_bits(nw, ne, sw, se, leaves, walls, G):
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
            G[WALL_PLANE, i] = np.uint64(0)
    G[0, 0] = G[0, 17] = G[1, 0] = G[1, 17] = np.uint64(0)


@njit(cache=True, inline="always")
def centre_leaf(p, G, leaves, lslots, meta):
    """The leaf of the centre 16 x 16 of plane ``p`` with the wall of plane 2 (zeros if
    there is none: ``load``); -1 if the leaf table is full."""
    for half in range(2):
        plane = p if half == 0 else WALL_PLANE
        for w in range(4):
            a, b = G[plane, 5 + 2 * w], G[plane, 6 + 2 * w]
            G[CENTRE_PLANE, 4 * half + w] = \
                ((a >> np.uint64(8)) & HALF) | (((a >> np.uint64(40)) & HALF) << U16) | \
                (((b >> np.uint64(8)) & HALF) << U32) | \
                (((b >> np.uint64(40)) & HALF) << np.uint64(48))
    return leaf(G, CENTRE_PLANE, 0, leaves, lslots, meta)


@njit(cache=True, inline="always")
def _sum3(x):
    """Two bits of x << 1 + x + x >> 1 at each bit."""
    left, right = x << U1, x >> U1
    return left ^ x ^ right, (left & x) | (right & (left ^ x))


@njit(cache=True, inline="always")
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


@njit(cache=True, inline="always")
def _hit(n0, n1, n2, n3, x, v0, v1, v2, v3, keep, flip):
    """Where the block sum n0..n3 is the term's and the centre x is of its kind."""
    return ~((n0 ^ v0) | (n1 ^ v1) | (n2 ^ v2) | (n3 ^ v3)) & (keep | (x ^ flip))


@njit(cache=True, inline="always")
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
        G[d, i] = (hit | (G[d, i] & more)) & ~G[WALL_PLANE, i]


@njit(cache=True, inline="always")
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
        G[d, i] = (top | (bottom << U32)) & ~G[WALL_PLANE, i]


# A call, not IR-inlined into the recursion (where it was inlined twice): a cold first run
# of `ca run --engine hashlife` took 29 s of CPU instead of 42 with the same jump times
# (docs/perf/startup.md).  Without numba's runtime, like the recursion, so the call passes
# its arrays without atomic reference counts (the reason the inlining was measured faster).
# One copy of each kernel's pass (not one per kind of wall or of pair): a first compile's
# time grows with every inlined copy.
@njit(cache=True, _nrt=False)
def advance_bits(node, gens, nodes, slots, leaves, lslots, meta, R, G):
    """The centre leaf of level-5 ``node`` after ``gens`` (0..8) generations; -1 if the
    leaf table is full.  (The arguments are the recursion's; ``slots`` is not needed.)"""
    walls = meta[HAS_WALL] != 0  # no wall anywhere until a bounded plane was framed
    load_bits(np.int64(nodes[node, 0]), np.int64(nodes[node, 1]), np.int64(nodes[node, 2]),
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
    return centre_leaf(s, G, leaves, lslots, meta)


# ---- the value leaves' base case ----
# The base case of value leaves: a node of the base level to its centre after T
# generations, by running the rules (``generation``) on its cells as a grid of
# life-form values.
#
# The scratch ``G`` is the recursion's (uint64, four square planes of the base node's side,
# one above the other: plane p, row y is G[p * side + y]), read here as int64: planes 0 and 1
# hold this and the next generation, plane 2 node ids while a centre is built, plane 3 the
# messages.  The rules arrive packed as uint64 (the recursion's one type for both kinds of
# leaf) and are read as int64.
@njit(cache=True, inline="always", _nrt=False)
def to_grid(node, level, G, p, nodes):
    """Write the cells of ``node`` into plane ``p`` of G, splitting in place."""
    side = np.int64(1) << level
    P = p * G.shape[1]
    G[P, 0] = node
    half = side
    while half > 1:
        quarter = half >> 1
        for y in range(0, side, half):
            for x in range(0, side, half):
                n = G[P + y, x]
                G[P + y, x] = nodes[n, 0]
                G[P + y, x + quarter] = nodes[n, 1]
                G[P + y + quarter, x] = nodes[n, 2]
                G[P + y + quarter, x + quarter] = nodes[n, 3]
        half = quarter


@njit(cache=True, inline="always", _nrt=False)
def from_grid(G, p, y0, x0, level, nodes, slots, meta):
    """The node of the 2**level square at (y0, x0) of plane ``p``, built bottom-up in
    plane 2; -1 if the table is full."""
    side = np.int64(1) << level
    P, W = p * G.shape[1], 2 * G.shape[1]
    for y in range(side):
        for x in range(side):
            G[W + y, x] = G[P + y0 + y, x0 + x]
    step = np.int64(1)
    k = np.int64(1)
    while step < side:
        for y in range(0, side, 2 * step):
            for x in range(0, side, 2 * step):
                n = join(G[W + y, x], G[W + y, x + step], G[W + y + step, x],
                         G[W + y + step, x + step], k, nodes, slots, meta)
                if n < 0:
                    return np.int64(-1)
                G[W + y, x] = n
        step *= 2
        k += 1
    return np.int64(G[W, 0])


@njit(cache=True, _nrt=False)
def advance_values(node, T, nodes, slots, leaves, lslots, meta, R, G):
    """Centre of base-level ``node`` after T generations (0: its centre as it is)."""
    level = np.int64(nodes[node, LEVEL])
    n = np.int64(1) << level
    r = meta[REACH]
    cells = G.view(np.int64)
    rules = R.view(np.int64)
    to_grid(node, level, cells, np.int64(0), nodes)
    s = np.int64(0)
    for g in range(1, T + 1):
        lo = n // 4 - (T - g) * r  # only what the later generations still need
        generation(cells, s, 1 - s, lo, n - lo, rules)
        s = 1 - s
    return from_grid(cells, s, n // 4, n // 4, level - 1, nodes, slots, meta)


# ---- a tree's levels ----
# Leaves to the plane's level-16 tree (from their Morton keys), for either kind of leaf.
@njit(cache=True)
def levels(keys, ids, n, level, nodes, slots, meta):
    """The plane's node above ``n`` nodes (or leaves) of ``level``, sorted by their Morton
    keys (distinct): each level groups runs of equal key >> 2 into a parent, absent
    quadrants empty; -1 if the table is full.  Overwrites keys and ids."""
    if n == 0:
        return np.int64(meta[EMPTY + PLANE_LEVEL])
    for lv in range(level, PLANE_LEVEL):
        m = 0
        i = 0
        while i < n:
            parent = keys[i] >> 2
            # the quadrants in scalars: an array here compiled numpy's allocation and
            # slice assignment into the first run (~0.2 s)
            q0 = q1 = q2 = q3 = np.int64(meta[EMPTY + lv])
            while i < n and keys[i] >> 2 == parent:
                q = keys[i] & 3
                if q == 0:
                    q0 = ids[i]
                elif q == 1:
                    q1 = ids[i]
                elif q == 2:
                    q2 = ids[i]
                else:
                    q3 = ids[i]
                i += 1
            node = join(q0, q1, q2, q3, np.int64(lv + 1), nodes, slots, meta)
            if node < 0:
                return np.int64(-1)
            keys[m] = parent
            ids[m] = node
            m += 1
        n = m
    return np.int64(ids[0])


@njit(cache=True, inline="always")
def tile_key(tx, ty, bits):
    """Interleaved bits (x in the even bits): sorting by it groups every quadtree square."""
    m = np.int64(0)
    for bit in range(bits):
        m |= ((tx >> bit) & 1) << (2 * bit)
        m |= ((ty >> bit) & 1) << (2 * bit + 1)
    return m


MASK_LEVEL = 6  # nodes of 64 cells square keep their row / column occupancy in one uint64


@njit(cache=True, inline="always")
def _popcount(w):
    w = w - ((w >> np.uint64(1)) & np.uint64(0x5555555555555555))
    w = (w & np.uint64(0x3333333333333333)) + ((w >> np.uint64(2)) & np.uint64(0x3333333333333333))
    w = (w + (w >> np.uint64(4))) & np.uint64(0x0F0F0F0F0F0F0F0F)
    return np.int64((w * np.uint64(0x0101010101010101)) >> np.uint64(56))


@njit(cache=True, inline="always")
def _leaf_count(t, form, leaves, meta):
    """Cells of leaf ``t`` holding life-form ``form`` (0: any live cell)."""
    if meta[LEAF] == 0:
        live = 0 < t < WALL
        return np.int64(1 if live and (form == 0 or t == form) else 0)
    if form > 1:
        return np.int64(0)
    return (_popcount(leaves[t, 0]) + _popcount(leaves[t, 1]) + _popcount(leaves[t, 2])
            + _popcount(leaves[t, 3]))


@njit(cache=True)
def count(node, level, form, memo, nodes, leaves, meta):
    """Cells of ``node`` holding life-form ``form`` (0: any live cell); each node counted
    once (memo -1 = not yet)."""
    if level == meta[LEAF]:
        return _leaf_count(node, form, leaves, meta)
    if node == meta[EMPTY + level]:
        return np.int64(0)
    m = memo[node]
    if m >= 0:
        return m
    total = np.int64(0)
    for q in range(4):
        total += count(np.int64(nodes[node, q]), level - 1, form, memo, nodes, leaves, meta)
    memo[node] = total
    return total


@njit(cache=True)
def _leaf_mask(t, axis, leaves, meta):
    """Bit i set: row (axis 0) or column (axis 1) i of leaf t has a live cell."""
    if meta[LEAF] == 0:
        return np.uint64(1) if 0 < t < WALL else np.uint64(0)
    m = np.uint64(0)
    for y in range(16):
        row = (leaves[t, y >> 2] >> np.uint64(16 * (y & 3))) & HALF
        if axis == 0:
            if row:
                m |= np.uint64(1) << np.uint64(y)
        else:
            m |= row
    return m


@njit(cache=True)
def _mask(node, level, axis, memo, done, nodes, leaves, meta):
    """The occupancy bits of ``node`` (level <= 6): rows (axis 0), north half low bits;
    or columns (axis 1), west half low bits."""
    if level == meta[LEAF]:
        return _leaf_mask(node, axis, leaves, meta)
    if done[node]:
        return memo[node]
    h = np.uint64(1) << np.uint64(level - 1)
    k = level - 1
    nw = _mask(np.int64(nodes[node, 0]), k, axis, memo, done, nodes, leaves, meta)
    ne = _mask(np.int64(nodes[node, 1]), k, axis, memo, done, nodes, leaves, meta)
    sw = _mask(np.int64(nodes[node, 2]), k, axis, memo, done, nodes, leaves, meta)
    se = _mask(np.int64(nodes[node, 3]), k, axis, memo, done, nodes, leaves, meta)
    if axis == 0:
        m = (nw | ne) | ((sw | se) << h)
    else:
        m = (nw | sw) | ((ne | se) << h)
    memo[node] = m
    done[node] = 1
    return m


# Exported itself (no wrapper for the plane's level: each kernel Python calls is another
# compile of everything it calls, ~0.2 s of a first run).
@njit(cache=True)
def occupy(node, level, y0, x0, axis, out, memo, done, nodes, leaves, meta):
    """OR the occupancy of ``node`` at (y0, x0) into ``out`` (64 rows / columns a word)."""
    if node == meta[EMPTY + level]:
        return
    if level == MASK_LEVEL:
        at = y0 if axis == 0 else x0
        out[at >> MASK_LEVEL] |= _mask(node, level, axis, memo, done, nodes, leaves, meta)
        return
    h = np.int64(1) << (level - 1)
    k = level - 1
    nw, ne, sw, se = np.int64(nodes[node, 0]), np.int64(nodes[node, 1]), \
        np.int64(nodes[node, 2]), np.int64(nodes[node, 3])
    # Two equal quadrants side by side along the axis cover the same rows (columns): one
    # visit (a plane filled with a regular pattern is otherwise a million visits).
    occupy(nw, k, y0, x0, axis, out, memo, done, nodes, leaves, meta)
    if axis == 0:
        if ne != nw:
            occupy(ne, k, y0, x0 + h, axis, out, memo, done, nodes, leaves, meta)
        occupy(sw, k, y0 + h, x0, axis, out, memo, done, nodes, leaves, meta)
        if se != sw:
            occupy(se, k, y0 + h, x0 + h, axis, out, memo, done, nodes, leaves, meta)
    else:
        if sw != nw:
            occupy(sw, k, y0 + h, x0, axis, out, memo, done, nodes, leaves, meta)
        occupy(ne, k, y0, x0 + h, axis, out, memo, done, nodes, leaves, meta)
        if se != ne:
            occupy(se, k, y0 + h, x0 + h, axis, out, memo, done, nodes, leaves, meta)


@njit(cache=True)
def morton(xs, ys, shift, keys):
    """Morton keys of the leaves (of 2**shift cells square) holding the cells, into keys."""
    for i in range(xs.shape[0]):
        keys[i] = tile_key(xs[i] >> shift, ys[i] >> shift, PLANE_LEVEL - shift)


# The arrays come from Python and are written over: no allocation here (numba's compiled
# numpy allocations and slice assignments were a fifth of this kernel's first compile).
@njit(cache=True)
def from_cells(keys, xs, ys_or_values, words, nodes, slots, leaves, lslots, meta):
    """The plane's node from cells sorted by leaf key (``morton``): value leaves are the
    cells' values (``ys_or_values``; keys distinct), bit leaves are made from the cells'
    low bits (``xs``, ``ys_or_values``: columns and rows; ``words``: one leaf's rows); then
    the levels above; -1 if a table is full.  Overwrites keys and ys_or_values."""
    n = keys.shape[0]
    low = meta[LEAF]
    if low == 0:
        return levels(keys, ys_or_values, n, low, nodes, slots, meta)
    m = 0
    i = 0
    while i < n:  # leaf m's key and id go where the cells read already were (m <= i)
        key = keys[i]
        for w in range(8):
            words[0, w] = 0
        while i < n and keys[i] == key:
            y, x = ys_or_values[i] & 15, xs[i] & 15
            words[0, y >> 2] |= np.uint64(1) << np.uint64(16 * (y & 3) + x)
            i += 1
        t = leaf(words, 0, 0, leaves, lslots, meta)
        if t < 0:
            return np.int64(-1)
        keys[m] = key
        ys_or_values[m] = t
        m += 1
    return levels(keys, ys_or_values, np.int64(m), low, nodes, slots, meta)


@njit(cache=True)
def any_live(node, level, y0, x0, top, bottom, left, right, nodes, leaves, meta):
    """Whether ``node`` (its corner at y0, x0) has a live cell in rows top..bottom-1,
    columns left..right-1."""
    side = np.int64(1) << level
    if (node == meta[EMPTY + level] or y0 >= bottom or y0 + side <= top or x0 >= right
            or x0 + side <= left):
        return False
    if level == meta[LEAF]:
        if level == 0:
            return 0 < node < WALL
        for y in range(max(top - y0, 0), min(bottom - y0, 16)):
            row = (leaves[node, y >> 2] >> np.uint64(16 * (y & 3))) & np.uint64(0xFFFF)
            for x in range(max(left - x0, 0), min(right - x0, 16)):
                if (row >> np.uint64(x)) & np.uint64(1):
                    return True
        return False
    h = side >> 1
    k = level - 1
    for q in range(4):
        if any_live(np.int64(nodes[node, q]), k, y0 + h * (q >> 1), x0 + h * (q & 1), top,
                     bottom, left, right, nodes, leaves, meta):
            return True
    return False


@njit(cache=True)
def grid_leaves(top, left, grid, nodes, slots, leaves, lslots, meta, keys, ids):
    """Each 16 x 16 tile of the plane a uint8 grid (nonzero = live, its cell (0, 0) at
    (left, top)) covers, as a bit leaf straight from the grid's bytes (no cell list): their
    Morton keys and ids into ``keys`` and ``ids``; returns how many (-1: table full)."""
    h, w = grid.shape
    ty0, ty1 = top >> BIT_LEAF_LEVEL, (top + h - 1) >> BIT_LEAF_LEVEL
    tx0, tx1 = left >> BIT_LEAF_LEVEL, (left + w - 1) >> BIT_LEAF_LEVEL
    words = np.zeros((1, 8), np.uint64)
    m = 0
    for ty in range(ty0, ty1 + 1):
        for tx in range(tx0, tx1 + 1):
            for i in range(8):  # (a slice assignment compiles numpy's broadcasting)
                words[0, i] = 0
            live = False
            for y in range(16):
                gy = (ty << BIT_LEAF_LEVEL) + y - top
                if gy < 0 or gy >= h:
                    continue
                row = np.uint64(0)
                for x in range(16):
                    gx = (tx << BIT_LEAF_LEVEL) + x - left
                    if gx >= 0 and gx < w and grid[gy, gx] != 0:
                        row |= np.uint64(1) << np.uint64(x)
                if row:
                    live = True
                    words[0, y >> 2] |= row << np.uint64(16 * (y & 3))
            if not live:
                continue
            t = leaf(words, 0, 0, leaves, lslots, meta)
            if t < 0:
                return np.int64(-1)
            keys[m] = tile_key(tx, ty, PLANE_LEVEL - BIT_LEAF_LEVEL)
            ids[m] = t
            m += 1
    return np.int64(m)


@njit(cache=True)
def build(keys, ids, n, level, nodes, slots, meta):
    """``levels`` for Python."""
    return levels(keys, ids, n, level, nodes, slots, meta)


@njit(cache=True)
def _emit(node, level, y0, x0, nodes, leaves, meta, out, n):
    """Append (y, x, value) of the live cells of ``node`` to ``out`` from row ``n``."""
    if level == meta[LEAF]:
        if level == 0:
            if 0 < node < WALL:
                out[n, 0], out[n, 1], out[n, 2] = y0, x0, node
                n += 1
            return n
        for y in range(16):
            row = (leaves[node, y >> 2] >> np.uint64(16 * (y & 3))) & np.uint64(0xFFFF)
            for x in range(16):
                if (row >> np.uint64(x)) & np.uint64(1):
                    out[n, 0], out[n, 1], out[n, 2] = y0 + y, x0 + x, 1
                    n += 1
        return n
    if node == meta[EMPTY + level]:
        return n
    h = np.int64(1) << (level - 1)
    k = level - 1
    n = _emit(np.int64(nodes[node, 0]), k, y0, x0, nodes, leaves, meta, out, n)
    n = _emit(np.int64(nodes[node, 1]), k, y0, x0 + h, nodes, leaves, meta, out, n)
    n = _emit(np.int64(nodes[node, 2]), k, y0 + h, x0, nodes, leaves, meta, out, n)
    return _emit(np.int64(nodes[node, 3]), k, y0 + h, x0 + h, nodes, leaves, meta, out, n)


@njit(cache=True)
def listing(node, nodes, leaves, meta):
    """(y, x, value) rows of the live cells of the plane ``node``, in quadtree order."""
    top = np.int64(PLANE_LEVEL)
    memo = np.full(meta[N_NODES], -1, np.int64)
    out = np.empty((count(node, top, np.int64(0), memo, nodes, leaves, meta), 3), np.int64)
    _emit(node, top, np.int64(0), np.int64(0), nodes, leaves, meta, out, np.int64(0))
    return out


NODE_TABLE, LEAF_TABLE = 1, 2  # rehash's ``which``: bits of the tables to enter anew


# ---- the store's upkeep ----
# The store's upkeep: entering every entry into fresh hash indexes (after a table grew)
# and garbage collection (when the memory limit stops the doubling), for either kind of leaf.
# Their own module and kernel group: a run whose tables never fill (the README's Life runs)
# does not compile them, and the first run that does fill announces them (a short notice).
@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True, inline="always")
def _q(nodes, n, q):
    return np.int64(nodes[np.uint64(n), q])  # unsigned: no test for a negative index


@njit(cache=True, inline="always")
def _centre(n, h, nodes, slots, meta):
    """The centre half of ``n`` (of level h > the leaves' + 1; no time passes); -1 if a
    table is full."""
    return join(_q(nodes, _q(nodes, n, 0), 3), _q(nodes, _q(nodes, n, 1), 2),
                _q(nodes, _q(nodes, n, 2), 1), _q(nodes, _q(nodes, n, 3), 0), h - 1, nodes,
                slots, meta)


@njit(cache=True, inline="always")
def _known(n, T, level, nodes, meta):
    """The result of ``n`` (of ``level``) for T generations if it is known without
    recursing — an empty or wall node's, or memoised — else -2 (-1: n is -1)."""
    if n < 0:
        return n
    e, w = np.uint64(EMPTY + level), np.uint64(WALL_AT + level)  # unsigned: no tests for
    if n == meta[e]:  # negative indices
        return meta[e - np.uint64(1)]
    if n == meta[w]:
        return meta[w - np.uint64(1)]
    u = np.uint64(n)
    if T == np.int64(1) << (level - 2 - meta[SHIFT]):
        if nodes[u, FULL] > 0:
            return np.int64(nodes[u, FULL])
    elif nodes[u, RESJ] == T + 1:
        return np.int64(nodes[u, RES])
    return np.int64(-2)


def _leaf_step(node, T, nodes, slots, leaves, lslots, meta, R, G):
    """The leaf kernel each copy of ``_recursion`` calls in its place (``advance_bits`` or
    ``advance_values``): the centre of base-level ``node`` after T generations (0: its
    centre as it is)."""
    raise NotImplementedError("bound per kind of leaf by _one_kind")


# _nrt=False: the recursion allocates nothing, and without numba's runtime its array
# arguments are not reference counted — perf showed those atomic counts taking half the time
# of small jumps (gun 1.6 -> 0.7 ms, spacefiller 1.7 -> 0.8, puffer 95 -> 77).  A template,
# compiled once per kind of leaf (below), ``_leaf_step`` bound to its leaf kernel.
def _recursion(node, T, nodes, slots, leaves, lslots, meta, R, G):
    """Centre of ``node`` after T generations (1 <= T <= 2**(level - 2 - s)); -1 if a table
    is full.  The tables are arrays, nine arguments (numba passes each as its struct's 7 to
    9 fields): an int64 array of their addresses, rebuilt inside as arrays owning nothing,
    took 3 arguments and was 5-10 % faster, but an ownerless array must never escape."""
    k = np.int64(nodes[np.uint64(node), LEVEL])
    found = _known(node, T, k, nodes, meta)  # (the recursion's callers looked already:
    if found != -2:  # this is for the first call, saving Python a kernel of its own)
        return found
    if k == meta[BASE]:
        out = _leaf_step(node, T, nodes, slots, leaves, lslots, meta, R, G)
    else:
        h = k - 1
        t2 = min(T, np.int64(1) << (k - 3 - meta[SHIFT]))  # the four's: full speed if it can
        t1 = T - t2  # the nine's (0: their centres as they are)
        a, b, c, d = _q(nodes, node, 0), _q(nodes, node, 1), _q(nodes, node, 2), \
            _q(nodes, node, 3)
        # The nine, row by row, in this level's frame: 0..8, their results 9..17, the four
        # 18..21, theirs 22..25.  (A tuple indexed in the loop cost two indirect jumps an
        # iteration: LLVM does not unroll a loop around a recursive call.)
        f = FRAMES + FRAME * k
        fr = meta[f:f + FRAME]  # (a view: indices known >= 0, no negative-index tests)
        fr[0] = a
        fr[1] = join(_q(nodes, a, 1), _q(nodes, b, 0), _q(nodes, a, 3), _q(nodes, b, 2), h,
                     nodes, slots, meta)
        fr[2] = b
        fr[3] = join(_q(nodes, a, 2), _q(nodes, a, 3), _q(nodes, c, 0), _q(nodes, c, 1), h,
                     nodes, slots, meta)
        fr[4] = join(_q(nodes, a, 3), _q(nodes, b, 2), _q(nodes, c, 1), _q(nodes, d, 0), h,
                     nodes, slots, meta)
        fr[5] = join(_q(nodes, b, 2), _q(nodes, b, 3), _q(nodes, d, 0), _q(nodes, d, 1), h,
                     nodes, slots, meta)
        fr[6] = c
        fr[7] = join(_q(nodes, c, 1), _q(nodes, d, 0), _q(nodes, c, 3), _q(nodes, d, 2), h,
                     nodes, slots, meta)
        fr[8] = d
        for i in range(9):
            n = fr[i]
            if n < 0:
                return np.int64(-1)
            if t1 > 0:
                v = _known(n, t1, h, nodes, meta)
                if v == -2:
                    v = _recursion(n, t1, nodes, slots, leaves, lslots, meta, R, G)
            elif h == meta[LEAF] + 1:  # quadrants of leaves: the leaf kernel, 0 generations
                v = _leaf_step(n, np.int64(0), nodes, slots, leaves, lslots, meta, R, G)
            else:
                v = _centre(n, h, nodes, slots, meta)
            if v < 0:
                return np.int64(-1)
            fr[9 + i] = v
        for i in range(4):  # the four: rows y, y+1 and columns x, x+1 of the nine's results
            r = 9 + 3 * (i >> 1) + (i & 1)
            fr[18 + i] = join(fr[r], fr[r + 1], fr[r + 3], fr[r + 4], h, nodes, slots, meta)
        for i in range(4):
            n = fr[18 + i]
            if n < 0:
                return np.int64(-1)
            v = _known(n, t2, h, nodes, meta)
            if v == -2:
                v = _recursion(n, t2, nodes, slots, leaves, lslots, meta, R, G)
            if v < 0:
                return np.int64(-1)
            fr[22 + i] = v
        out = join(fr[22], fr[23], fr[24], fr[25], h, nodes, slots, meta)
    u = np.uint64(node)
    if out >= 0 and T == np.int64(1) << (k - 2 - meta[SHIFT]):
        nodes[u, FULL] = out
    elif out >= 0:
        nodes[u, RES] = out
        nodes[u, RESJ] = T + 1
    return out


def _one_kind(template: Any, name: str, **bindings: Any) -> Any:
    """``template``'s code as a kernel named ``name`` (numba's cache names its index after
    it: one per kind, each with one signature) whose globals in ``bindings`` are bound to
    those kernels, and whose own name is bound to itself (the recursion recurses into its
    own kind).  A run compiles only its own kind of leaf (a run-time branch on the kind
    compiled both: 2 s more of a first run's compile)."""
    namespace = dict(template.__globals__, **bindings)
    fn = FunctionType(template.__code__, namespace, name, template.__defaults__)
    fn.__qualname__, fn.__module__, fn.__doc__ = name, template.__module__, template.__doc__
    kernel = njit(cache=True, _nrt=False)(fn)
    namespace[template.__name__] = kernel
    return kernel


step_bits = _one_kind(_recursion, "step_bits", _leaf_step=advance_bits)
step_values = _one_kind(_recursion, "step_values", _leaf_step=advance_values)
