"""The one HashLife tree an engine adopts as its universe, and the jumps with their memory
handling, whatever the leaves are.

A run (a rule set's node table plus its leaf strategy: ``generic.GenericRun``, leaves of
life-form values, or ``bits.run.BitRun``, 16 x 16-cell leaves of bits) answers the
questions that depend on the leaves — building a plane from cells, one jump, the census —
and this module does the rest once: the tree's cached statistics, the renumbering on
garbage collection, growing the table or collecting and retrying when it fills, and as a
last resort two jumps of half the length.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from camlab88.apps.ca.hashlife.plane import frame


class Run(Protocol):
    """A rule set's node table and its leaf strategy."""

    store: object  # a table with epoch, trees, grow_if_full, make_room, crowded, full_error

    def build(self, engine) -> int:
        """The engine's cells (or dense window) as a plane node; -1 if the table filled."""

    def next_jump(self, node: int, remaining: int, edges: str) -> int:
        """Generations of the next jump of at most ``remaining`` (0: step directly)."""

    def advance(self, framed: int, generations: int) -> int:
        """The centre of the framed plane after ``generations``; -1 if the table filled."""

    def population(self, node: int) -> int: ...

    def by_type(self, node: int, forms: int) -> dict[int, int]: ...

    def occupied(self, node: int, axis: int) -> np.ndarray: ...

    def cells(self, node: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]: ...


@dataclass(eq=False)  # hashed by identity: the store keeps its live trees in a WeakSet
class Tree:
    """A plane's state as a node of a run's table: the engine's universe after a jump.
    Valid while the epoch matches (collections renumber every live tree in place);
    statistics and the cell list are computed once and kept (nodes are immutable)."""

    run: Run
    epoch: int
    node: int
    _cache: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def store(self):
        return self.run.store

    def valid(self, store: object) -> bool:
        return self.store is store and self.epoch == self.store.epoch

    def _memo(self, key, compute):
        if key not in self._cache:
            if self.epoch != self.store.epoch:  # a bug: collections renumber live trees
                raise RuntimeError("a HashLife tree missed a garbage collection's renumbering")
            self._cache[key] = compute()
        return self._cache[key]

    def population(self) -> int:
        return self._memo("population", lambda: self.run.population(self.node))

    def by_type(self, forms: int) -> dict[int, int]:
        return dict(self._memo(("by_type", forms), lambda: self.run.by_type(self.node, forms)))

    def occupied(self) -> tuple[np.ndarray, np.ndarray]:
        return (self._memo(("occupied", 1), lambda: self.run.occupied(self.node, 1)),
                self._memo(("occupied", 0), lambda: self.run.occupied(self.node, 0)))

    def cells(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return self._memo("cells", lambda: self.run.cells(self.node))

    def window(self) -> None:
        return None


def adopt(run: Run, node: int) -> Tree:
    """The tree an engine adopts; the store renumbers it if it collects garbage later
    (another engine of these rules may hold its state only in a tree)."""
    tree = Tree(run, run.store.epoch, node)
    run.store.trees.add(tree)
    return tree


def plane(run: Run, engine) -> int:
    """The engine's plane as a node of ``run``: its tree if that is ours and valid, else
    built from its cells, growing or collecting the table as needed."""
    tree = engine.tree
    s = run.store
    if isinstance(tree, Tree) and tree.valid(s):
        return tree.node
    collected = False
    while True:  # a dense plane may need the table doubled several times
        node = run.build(engine)
        if node >= 0:
            return node
        if s.grow_if_full():
            continue
        if collected:
            break
        collected = True
        s.make_room([])
    raise MemoryError(f"the plane does not fit the HashLife memory limit "
                      f"({s.limit_bytes >> 20} MB)")


def jump(run: Run, node: int, generations: int, edges: str) -> int:
    """The plane ``node`` after ``generations``; on a full table grow it (within the memory
    limit) or collect garbage and retry, as a last resort two jumps of half the length."""
    s = run.store
    collected = False
    while True:
        try:
            out = run.advance(frame(s, node, edges), generations)
        except MemoryError:  # framing the plane found the table full
            out = -1
        if out >= 0:
            return out
        if s.grow_if_full():
            continue
        if collected:
            break
        collected = True
        (node,) = s.make_room([node])
        if s.crowded:
            break
    if generations == 1:
        raise s.full_error()
    first = generations // 2
    return jump(run, jump(run, node, first, edges), generations - first, edges)
