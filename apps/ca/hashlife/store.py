"""HashLife's one node store (numba open addressing), for either kind of leaf.

Nodes of the levels above the leaves are rows of ``nodes`` (int32 x 8): quadrants nw, ne,
sw, se; a memoised result for some T generations and 1 + T (0: none); the level; the
memoised result at full speed (0: none).  Two memos, as one pass of any length asks a
level for two lengths (evolve.py), which would otherwise evict each other's results.  A
node's key is its quadrants and its level (leaf and node ids overlap).

The quadrants of the lowest nodes (level ``leaf + 1``) are leaf ids, by kind of leaf:

* values (``leaf`` 0, any deterministic rules): the leaf is one cell and its id is the
  life-form value itself (0 dead, 1..65535) or ``WALL``, the outside of a bounded plane;
  the leaf table stays empty;
* bits (``leaf`` 4, binary rules): 16 x 16 cells, a row of ``leaves`` (uint64 x 8): words
  0..3 the live cells (row y in bits 16*(y%4).. of word y//4, column x in bit x of its
  row), words 4..7 the same for the wall; leaf 1 is the empty leaf, leaf 2 the all-wall
  leaf.

Id 0 of either table is never a node or table leaf (0 marks an empty hash slot).  ``meta``
packs the counts, the leaf geometry, the empty and wall towers and a flag, so kernels take
one array for them (numba reference-counts every array argument of every call); then the
tables' addresses and sizes (``publish``: kernels the recursion calls find the tables from
meta's address alone) and a frame per level for the recursion (evolve.py).  Kernels
return -1 when a table is full; the caller grows it or collects garbage and retries.
"""

from __future__ import annotations

import weakref

import numpy as np
from camlab88.base import raw_views
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__, sources=("camlab88.base.raw_views",
                                        "camlab88.base.raw_view_intrinsics"))

TOP_LEVEL = 17  # the 65536-square plane is level 16; stepping frames it in a level-17 node
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
# The tables' addresses and sizes, written by the kernel Python calls for the kernels it
# calls to find them (base/raw_views.py): nodes, slots, leaves, leaf slots, rules, scratch;
# node and leaf rows, rule words, scratch rows and columns.
AT = WALL_AT + TOP_LEVEL + 1
AT_NODES, AT_SLOTS, AT_LEAVES, AT_LSLOTS, AT_RULES, AT_SCRATCH = range(AT, AT + 6)
N_ROWS, L_ROWS, R_WORDS, G_ROWS, G_COLUMNS = range(AT + 6, AT + 11)
META = AT + 11
# Then one frame per level for the recursion's nine and four squares and their results
# (evolve.py: a level's call only calls the level below, so one frame a level suffices).
FRAMES, FRAME = META, 32
META_SIZE = FRAMES + FRAME * (TOP_LEVEL + 1)
NODE_BYTES = 4 * ROW + 2 * 4  # a row and two hash slots (load factor at most 1/2)
LEAF_BYTES = 8 * 8 + 2 * 4

# The types Python passes (the exports' signatures).
NODES, SLOTS, LEAVES, META_T = "int32[:, ::1]", "int32[::1]", "uint64[:, ::1]", "int64[::1]"
TABLES = f"{NODES}, {SLOTS}, {LEAVES}, {SLOTS}, {META_T}"  # nodes, slots, leaves, lslots, meta


@kernels.kernel(inline="always")
def _hash4(a, b, c, d, mask):
    h = (np.uint64(a) * np.uint64(0x9E3779B97F4A7C15)
         ^ np.uint64(b) * np.uint64(0xC2B2AE3D27D4EB4F)
         ^ np.uint64(c) * np.uint64(0x165667B19E3779F9)
         ^ np.uint64(d) * np.uint64(0x85EBCA77C2B2AE63))
    return np.int64((h ^ (h >> np.uint64(29))) & np.uint64(mask))


@kernels.kernel(inline="always")
def node_hash(a, b, c, d, level, mask):
    return _hash4(a, b, c, np.int64(d) ^ (np.int64(level) << 27), mask)


@kernels.kernel(inline="always")
def _mix(h):
    h = (h ^ (h >> np.uint64(31))) * np.uint64(0x7FB5D329728EA185)
    return h ^ (h >> np.uint64(27))


# Odd multipliers of the leaf hash's eight words (splitmix, xxhash, murmur constants).
_LEAF_K = (0x9E3779B97F4A7C15, 0xC2B2AE3D27D4EB4F, 0x165667B19E3779F9, 0x85EBCA77C2B2AE63,
           0x27D4EB2F165667C5, 0xFF51AFD7ED558CCD, 0xC4CEB9FE1A85EC53, 0xD6E8FEB86659FD93)


@kernels.kernel(inline="always")
def leaf_hash(W, r, at, mask):
    # eight independent multiplies, one mixing at the end: eight mixing rounds chained one
    # after another were ~10 ns more a base case (a leaf looked up each)
    h = (W[r, at] * np.uint64(_LEAF_K[0]) + W[r, at + 1] * np.uint64(_LEAF_K[1])
         + W[r, at + 2] * np.uint64(_LEAF_K[2]) + W[r, at + 3] * np.uint64(_LEAF_K[3])
         + W[r, at + 4] * np.uint64(_LEAF_K[4]) + W[r, at + 5] * np.uint64(_LEAF_K[5])
         + W[r, at + 6] * np.uint64(_LEAF_K[6]) + W[r, at + 7] * np.uint64(_LEAF_K[7]))
    return np.int64(_mix(h) & np.uint64(mask))


@kernels.kernel(inline="always")
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
@kernels.export(f"int64(int64, int64, int64, int64, int64, {NODES}, {SLOTS}, {META_T})",
                _nrt=False)
def join(a, b, c, d, level, nodes, slots, meta):
    """The node of ``level`` with quadrants a, b, c, d (nw, ne, sw, se), made at most
    once; -1 if the table is full."""
    return _join(a, b, c, d, level, nodes, slots, meta)


@kernels.kernel(inline="always")
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


@kernels.export(f"int64(uint64[:, ::1], {TABLES})")
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


@kernels.kernel(inline="always")
def publish(nodes, slots, leaves, lslots, meta, R, G):
    """Write the tables' (and the rules' and scratch's) addresses and sizes into ``meta``;
    its own address, which is what the kernels called with it take."""
    meta[AT_NODES], meta[AT_SLOTS] = raw_views.address(nodes), raw_views.address(slots)
    meta[AT_LEAVES], meta[AT_LSLOTS] = raw_views.address(leaves), raw_views.address(lslots)
    meta[AT_RULES], meta[AT_SCRATCH] = raw_views.address(R), raw_views.address(G)
    meta[N_ROWS], meta[L_ROWS], meta[R_WORDS] = nodes.shape[0], leaves.shape[0], R.shape[0]
    meta[G_ROWS], meta[G_COLUMNS] = G.shape[0], G.shape[1]
    return raw_views.address(meta)


@kernels.kernel(inline="always")
def node_tables(at):
    """(nodes, slots, meta) from meta's address (``publish``)."""
    meta = raw_views.vector_at(at, META_SIZE, np.int64(0))
    n = meta[N_ROWS]
    return (raw_views.matrix_at(meta[AT_NODES], n, ROW, np.int32(0)),
            raw_views.vector_at(meta[AT_SLOTS], 2 * n, np.int32(0)), meta)


@kernels.kernel(inline="always")
def all_tables(at):
    """(nodes, slots, leaves, lslots, meta, R, G) from meta's address (``publish``)."""
    nodes, slots, meta = node_tables(at)
    m = meta[L_ROWS]
    return (nodes, slots, raw_views.matrix_at(meta[AT_LEAVES], m, 8, np.uint64(0)),
            raw_views.vector_at(meta[AT_LSLOTS], 2 * m, np.int32(0)), meta,
            raw_views.vector_at(meta[AT_RULES], meta[R_WORDS], np.uint64(0)),
            raw_views.matrix_at(meta[AT_SCRATCH], meta[G_ROWS], meta[G_COLUMNS], np.uint64(0)))


class Store:
    """One rule set's node table (and leaf table, for bit leaves), its memory limit and
    garbage collection.  ``leaf``: the leaf level (0: values, 4: bits); ``base``: the level
    whose nodes the leaf kernel advances; ``shift``, ``reach``: 2**shift >= the rules'
    reach."""

    def __init__(self, leaf: int, base: int, shift: int, reach: int,
                 limit_bytes: int = 512 << 20, nodes: int = 1 << 13, leaves: int = 1 << 12,
                 min_nodes: int = 1 << 12) -> None:
        # Small to start: a fresh page costs a fault at first touch, and the hash touches
        # them at random, so a big empty table is slower than doubling a small one.
        self.limit_bytes = int(limit_bytes)
        self.epoch = 0  # bumped by every collection: ids of older epochs are void
        # Trees engines hold (objects with .node and .epoch): kept and renumbered by every
        # collection, so an engine whose state is only a tree never loses it.
        self.trees: weakref.WeakSet = weakref.WeakSet()
        cap_l = max(2, min(leaves, 1 << 11)) if leaf else 2  # value leaves: no table
        cap_n = min_nodes
        while 2 * cap_n <= nodes and \
                self._bytes(2 * cap_n, 2 * cap_l if leaf else cap_l) <= self.limit_bytes:
            cap_n *= 2
            if leaf and 2 * cap_l <= leaves:
                cap_l *= 2
        if self._bytes(cap_n, cap_l) > self.limit_bytes:
            raise MemoryError(f"the HashLife memory limit ({self.limit_bytes >> 20} MB) is "
                              f"below the smallest node table "
                              f"({self._bytes(cap_n, cap_l) / 2**20:.1f} MB)")
        self.meta = np.zeros(META_SIZE, np.int64)
        self.meta[N_NODES] = self.meta[N_LEAVES] = 1
        self.meta[LEAF], self.meta[BASE], self.meta[SHIFT], self.meta[REACH] = \
            leaf, base, shift, reach
        self.nodes, self.slots = self._table(cap_n, ROW, np.int32)
        self.leaves, self.lslots = self._table(cap_l, 8, np.uint64)
        words = np.zeros((2, 8), np.uint64)  # the empty bit leaf, the all-wall bit leaf
        words[1, 4:] = np.uint64(0xFFFFFFFFFFFFFFFF)
        if towers(words, *self.tables) < 0:
            raise MemoryError("the HashLife node table cannot hold its fixed part")

    @staticmethod
    def _bytes(cap_n: int, cap_l: int) -> int:
        return cap_n * NODE_BYTES + cap_l * LEAF_BYTES

    @staticmethod
    def _table(cap: int, row: int, dtype: type) -> tuple[np.ndarray, np.ndarray]:
        # Zeros mean "none" (no memo, empty slot): the pages stay untouched until used.
        return np.zeros((cap, row), dtype), np.zeros(2 * cap, np.int32)

    @property
    def tables(self) -> tuple[np.ndarray, ...]:
        """(nodes, slots, leaves, lslots, meta): what most kernels take."""
        return self.nodes, self.slots, self.leaves, self.lslots, self.meta

    @property
    def leaf_level(self) -> int:
        return int(self.meta[LEAF])

    @property
    def empty(self) -> np.ndarray:
        return self.meta[EMPTY:EMPTY + TOP_LEVEL + 1]

    @property
    def wall(self) -> np.ndarray:
        return self.meta[WALL_AT:WALL_AT + TOP_LEVEL + 1]

    @property
    def count(self) -> int:
        return int(self.meta[N_NODES])

    @property
    def leaf_count(self) -> int:
        return int(self.meta[N_LEAVES])

    @property
    def bytes(self) -> int:
        return self.nodes.nbytes + self.slots.nbytes + self.leaves.nbytes + \
            self.lslots.nbytes

    def quadrants(self, node: int) -> tuple[int, int, int, int]:
        nw, ne, sw, se = self.nodes[node, :4].tolist()
        return nw, ne, sw, se

    def join(self, a: int, b: int, c: int, d: int, level: int) -> int:
        n = int(join(np.int64(a), np.int64(b), np.int64(c), np.int64(d), np.int64(level),
                     self.nodes, self.slots, self.meta))
        if n < 0:
            raise MemoryError("node table full")
        return n

    def mark_wall(self) -> None:
        """A bounded plane is framed: from now on the bit kernels look for walls in leaves."""
        self.meta[HAS_WALL] = 1

    def make_room(self, roots: list[int]) -> list[int]:
        """Collect garbage keeping ``roots`` (returned renumbered) and every live tree
        (renumbered in place); see ``crowded``."""
        live = [t for t in self.trees if t.epoch == self.epoch]
        keep = np.array([*roots, *(t.node for t in live)], np.int64)
        from camlab88.apps.ca.hashlife.upkeep import collect  # its own kernel group

        collect(keep, *self.tables)
        self.epoch += 1
        for tree, node in zip(live, keep[len(roots):], strict=True):
            tree.node, tree.epoch = int(node), self.epoch
        return [int(r) for r in keep[:len(roots)]]

    def _full(self) -> tuple[bool, bool]:
        return (10 * self.count > 9 * self.nodes.shape[0],
                10 * self.leaf_count > 9 * self.leaves.shape[0])

    @property
    def crowded(self) -> bool:
        """Whether a table is still (almost) full: collecting freed too little."""
        return any(self._full())

    def full_error(self) -> MemoryError:
        leaves = f"{self.leaf_count} leaves, " if self.leaf_level else ""
        return MemoryError(f"the HashLife node table is full ({self.count} nodes, {leaves}"
                           f"{self.bytes >> 20} MB) and the memory limit "
                           f"({self.limit_bytes >> 20} MB) allows no more")

    def grow_if_full(self) -> bool:
        """Grow whichever table is full instead of collecting while there is room (results
        survive growing, not collecting); False once the memory limit stops it.  Four
        times over while that fits the limit, else twice: every growth enters each entry
        anew (the puffer train's jump spent 6 of 38 ms doubling 8,192 nodes up to 131,072).
        """
        grow_nodes, grow_leaves = self._full()
        full = (self.nodes.nbytes + self.slots.nbytes if grow_nodes else 0) + \
            (self.leaves.nbytes + self.lslots.nbytes if grow_leaves else 0)
        factor = next((f for f in (4, 2) if self.bytes + (f - 1) * full <= self.limit_bytes),
                      0)
        if not full or not factor:
            return False
        from camlab88.apps.ca.hashlife.upkeep import LEAF_TABLE, NODE_TABLE, rehash  # its own group

        if grow_nodes:
            self.nodes, self.slots = self._grown(self.nodes, self.count, factor)
        if grow_leaves:
            self.leaves, self.lslots = self._grown(self.leaves, self.leaf_count, factor)
        rehash((NODE_TABLE if grow_nodes else 0) | (LEAF_TABLE if grow_leaves else 0),
               *self.tables)
        return True

    def _grown(self, table: np.ndarray, n: int,
               factor: int) -> tuple[np.ndarray, np.ndarray]:
        bigger, slots = self._table(factor * table.shape[0], table.shape[1], table.dtype)
        bigger[:n] = table[:n]
        return bigger, slots  # the slots empty: rehash enters every entry
