"""The hash-consed node table (numba open addressing) and its garbage collection.

Node ids below ``LEAF_IDS`` are level-0 nodes: the life-form value itself (0 = dead, 1..65535)
or ``WALL``, the outside of a bounded plane.  Every other id is a row of ``nodes``, created
at most once per distinct quadruple of quadrants by :func:`join`.  A row holds, packed in one
int32 array so the recursion passes one array (measured: numba reference-counts every array
argument of every call): the quadrants nw, ne, sw, se; the memoised result and 1 + the
generation exponent it is for (0: none); the level.  Kernels return -1 when the table is
full; the caller collects garbage or grows the table and tries again.
"""

from __future__ import annotations

import weakref

import numpy as np
from numba import njit

WALL = 65536  # level-0 value outside a bounded plane: never changes, sends nothing
LEAF_IDS = WALL + 1
TOP_LEVEL = 17  # the 65536-square plane is level 16; stepping frames it in a level-17 node
RES, RESJ, LEVEL = 4, 5, 6  # columns of a node row after its four quadrants
ROW = 8  # int32 per row (two spare: rows stay 32-byte aligned)
BYTES_PER_NODE = 4 * ROW + 2 * 4  # the row and two hash slots
MIN_CAPACITY = 1 << 17  # a power of two (so is the hash index, twice as long) > LEAF_IDS


@njit(cache=True, inline="always")
def _hash4(a, b, c, d, mask):
    h = (np.uint64(a) * np.uint64(0x9E3779B97F4A7C15)
         ^ np.uint64(b) * np.uint64(0xC2B2AE3D27D4EB4F)
         ^ np.uint64(c) * np.uint64(0x165667B19E3779F9)
         ^ np.uint64(d) * np.uint64(0x85EBCA77C2B2AE63))
    return np.int64((h ^ (h >> np.uint64(29))) & np.uint64(mask))


@njit(cache=True, inline="always")
def join(a, b, c, d, nodes, slots, meta):
    """The node with quadrants a, b, c, d (nw, ne, sw, se; equal levels), made at most once;
    -1 if the table is full."""
    mask = slots.shape[0] - 1
    s = _hash4(a, b, c, d, mask)
    while True:
        i = slots[s]
        if i == 0:  # empty slot (real nodes have ids >= LEAF_IDS)
            break
        if nodes[i, 0] == a and nodes[i, 1] == b and nodes[i, 2] == c and nodes[i, 3] == d:
            return np.int64(i)
        s = (s + 1) & mask
    n = meta[0]
    if n >= nodes.shape[0]:
        return np.int64(-1)
    slots[s] = n
    nodes[n, 0] = a
    nodes[n, 1] = b
    nodes[n, 2] = c
    nodes[n, 3] = d
    nodes[n, RESJ] = 0
    nodes[n, LEVEL] = (nodes[a, LEVEL] if a >= LEAF_IDS else 0) + 1
    meta[0] = n + 1
    return np.int64(n)


@njit(cache=True)
def rehash(nodes, slots, n):
    """Enter nodes LEAF_IDS..n-1 (all distinct) into an empty hash index."""
    mask = slots.shape[0] - 1
    for i in range(LEAF_IDS, n):
        s = _hash4(np.int64(nodes[i, 0]), np.int64(nodes[i, 1]), np.int64(nodes[i, 2]),
                   np.int64(nodes[i, 3]), mask)
        while slots[s] != 0:
            s = (s + 1) & mask
        slots[s] = i


@njit(cache=True)
def collect(roots, nodes, slots, meta):
    """Keep only the nodes reachable from ``roots`` (renumbered, children before parents,
    as they were made), forget every memoised result, rebuild the hash; roots are rewritten
    with their new ids.  Returns the number of nodes kept."""
    n = meta[0]
    keep = np.zeros(n, np.uint8)
    stack = np.empty(4 * n + roots.shape[0], np.int64)
    top = 0
    for r in range(roots.shape[0]):
        stack[top] = roots[r]
        top += 1
    while top > 0:
        top -= 1
        i = stack[top]
        if i < LEAF_IDS or keep[i]:
            continue
        keep[i] = 1
        for q in range(4):
            stack[top] = nodes[i, q]
            top += 1
    new = np.arange(n, dtype=np.int64)
    m = LEAF_IDS
    for i in range(LEAF_IDS, n):
        if keep[i]:
            new[i] = m
            for q in range(4):
                nodes[m, q] = new[nodes[i, q]]
            nodes[m, RESJ] = 0
            nodes[m, LEVEL] = nodes[i, LEVEL]
            m += 1
    slots[:] = 0
    meta[0] = m
    rehash(nodes, slots, np.int64(m))
    for r in range(roots.shape[0]):
        roots[r] = new[roots[r]]
    return m


class NodeStore:
    """The arrays of one rule set's node table, its memory limit and garbage collection."""

    def __init__(self, capacity: int = 1 << 20, limit_bytes: int = 512 << 20) -> None:
        self.limit_bytes = int(limit_bytes)
        self.epoch = 0  # bumped by every collection: node ids of older epochs are void
        # Trees engines hold (objects with .node and .epoch), renumbered by every collection.
        self.trees: weakref.WeakSet = weakref.WeakSet()
        cap = MIN_CAPACITY
        while 2 * cap <= capacity and 2 * cap * BYTES_PER_NODE <= self.limit_bytes:
            cap *= 2
        if cap * BYTES_PER_NODE > self.limit_bytes:
            raise MemoryError(f"the HashLife memory limit ({self.limit_bytes >> 20} MB) is "
                              f"below the smallest node table "
                              f"({cap * BYTES_PER_NODE / 2**20:.1f} MB)")
        self._allocate(cap)
        self.empty = self._tower(0)
        self.wall = self._tower(WALL)

    def _allocate(self, cap: int) -> None:
        # Zeros mean "none" in both (no memo; empty slot), so the pages stay untouched
        # until used: allocating a large table costs nothing up front.
        self.nodes = np.zeros((cap, ROW), np.int32)
        self.slots = np.zeros(2 * cap, np.int32)  # load factor at most 1/2
        self.meta = np.array([LEAF_IDS], np.int64)

    @property
    def count(self) -> int:
        return int(self.meta[0])

    @property
    def capacity(self) -> int:
        return int(self.nodes.shape[0])

    @property
    def bytes(self) -> int:
        return self.nodes.nbytes + self.slots.nbytes

    def quadrants(self, node: int) -> tuple[int, int, int, int]:
        nw, ne, sw, se = (int(q) for q in self.nodes[node, :4])
        return nw, ne, sw, se

    def _tower(self, value: int) -> np.ndarray:
        """The uniform node of every level 0..TOP_LEVEL filled with ``value``."""
        ids = np.zeros(TOP_LEVEL + 1, np.int64)
        ids[0] = value
        for k in range(1, TOP_LEVEL + 1):
            ids[k] = self.join(*(int(ids[k - 1]),) * 4)
        return ids

    def join(self, a: int, b: int, c: int, d: int, level: int = 0) -> int:
        """The node of quadrants a, b, c, d (``level`` is implied by theirs here)."""
        n = int(join(np.int64(a), np.int64(b), np.int64(c), np.int64(d), self.nodes,
                     self.slots, self.meta))
        if n < 0:
            raise MemoryError("node table full")
        return n

    def mark_wall(self) -> None:
        """A bounded plane is framed (nothing to note: walls are level-0 values here)."""

    @property
    def crowded(self) -> bool:
        """Whether the table is still (almost) full: collecting freed too little."""
        return 10 * self.count > 9 * self.capacity

    def full_error(self) -> MemoryError:
        return MemoryError(f"the HashLife node table is full ({self.count} nodes, "
                           f"{self.bytes >> 20} MB) and the memory limit "
                           f"({self.limit_bytes >> 20} MB) allows no more")

    def make_room(self, roots: list[int]) -> list[int]:
        """Collect garbage keeping ``roots`` (returned renumbered) and every live tree an
        engine holds (renumbered in place: an engine whose state is only a tree survives
        another engine's collection); see ``crowded``."""
        live = [t for t in self.trees if t.epoch == self.epoch]
        n, towers = len(roots), 2 * (TOP_LEVEL + 1)
        keep = np.array([*roots, *self.empty, *self.wall, *(t.node for t in live)], np.int64)
        collect(keep, self.nodes, self.slots, self.meta)
        self.epoch += 1
        self.empty, self.wall = keep[n:n + TOP_LEVEL + 1], keep[n + TOP_LEVEL + 1:n + towers]
        for tree, node in zip(live, keep[n + towers:], strict=True):
            tree.node, tree.epoch = int(node), self.epoch
        return [int(r) for r in keep[:n]]

    def grow_if_full(self) -> bool:
        """Double the table instead of collecting while it is small (results survive
        growing, not collecting); False once the memory limit stops it."""
        if 2 * self.bytes > self.limit_bytes:
            return False
        self._grow()
        return True

    def _grow(self) -> None:
        """Double the table; every node keeps its id and its memoised result."""
        old, n = self.nodes, self.count
        self._allocate(2 * self.capacity)
        self.nodes[:n] = old[:n]
        self.meta[0] = n
        rehash(self.nodes, self.slots, np.int64(n))
