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
one array for them (numba reference-counts every array argument of every call); then a
frame per level for the recursion (evolve.py).  The layout's constants and every kernel
are in kernels.py.  Kernels
return -1 when a table is full; the caller grows it or collects garbage and retries.
"""

from __future__ import annotations

import weakref

import numpy as np

from camlab88.apps.ca.hashlife.kernels import (
    BASE,
    EMPTY,
    HAS_WALL,
    LEAF,
    LEAF_TABLE,
    META_SIZE,
    N_LEAVES,
    N_NODES,
    NODE_TABLE,
    REACH,
    ROW,
    SHIFT,
    TOP_LEVEL,
    WALL_AT,
    collect,
    join,
    rehash,
    towers,
)

# Odd multipliers of the leaf hash's eight words (splitmix, xxhash, murmur constants).
_LEAF_K = (0x9E3779B97F4A7C15, 0xC2B2AE3D27D4EB4F, 0x165667B19E3779F9, 0x85EBCA77C2B2AE63,
           0x27D4EB2F165667C5, 0xFF51AFD7ED558CCD, 0xC4CEB9FE1A85EC53, 0xD6E8FEB86659FD93)


NODE_BYTES = 4 * ROW + 2 * 4  # a row and two hash slots (load factor at most 1/2)
LEAF_BYTES = 8 * 8 + 2 * 4


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
