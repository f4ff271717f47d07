"""The binary path as the HashLife strategy uses it: a rule's tables, the jumps with their
memory handling, and the tree the engine adopts."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from apps.ca.hashlife.bits import census, convert, evolve
from apps.ca.hashlife.bits.frame import frame
from apps.ca.hashlife.bits.leaves import PLANES
from apps.ca.hashlife.bits.rule import BinaryRule, binary_rule
from apps.ca.hashlife.bits.store import BitStore
from apps.ca.rules import RuleSet

MAX_JUMP = 1 << 15  # generations: the level-17 frame's centre after at most 2**15


@dataclass(eq=False)  # hashed by identity: the store keeps its live trees in a WeakSet
class BitTree:
    """A binary plane's state as a node of a rule's tables (valid while the epoch matches);
    answers what the engine asks of a tree without listing the cells."""

    store: BitStore
    epoch: int
    node: int
    _census: dict = field(default_factory=dict, repr=False, compare=False)

    def valid(self, store: object) -> bool:
        return self.store is store and self.epoch == self.store.epoch

    def _check(self) -> None:
        """Node ids of an older epoch name other nodes: refuse rather than answer wrongly
        (collections renumber every live tree, BitStore.make_room, so this is a bug)."""
        if self.epoch != self.store.epoch:
            raise RuntimeError("a HashLife tree missed a garbage collection's renumbering")

    def by_type(self, forms: int) -> dict[int, int]:
        """{1: cells} (empty if none); ``forms`` is ignored: a binary plane has only 1s."""
        if "count" not in self._census:
            self._check()
            self._census["count"] = census.count(self.node, self.store)
        n = self._census["count"]
        return {1: n} if n else {}

    def occupied(self, axis: int) -> np.ndarray:
        """Sorted rows (axis 0) or columns (axis 1) that hold a live cell."""
        key = ("occupied", axis)
        if key not in self._census:
            self._check()
            self._census[key] = census.occupied(self.node, axis, self.store)
        return self._census[key]

    def cells(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(ys, xs, types) of the live cells, row by row."""
        self._check()
        s = self.store
        rows = convert.cells(np.int64(self.node), s.nodes, s.leaves, s.meta)
        return rows[:, 0].copy(), rows[:, 1].copy(), np.ones(rows.shape[0], np.int64)


@dataclass
class BitRun:
    """What one binary rule's jumps need: its tables, its kernel table and scratch rows."""

    store: BitStore
    rule: BinaryRule
    grids: np.ndarray = field(default_factory=lambda: np.zeros((PLANES, 32), np.uint64))

    @classmethod
    def of(cls, rules: RuleSet, memory: int) -> BitRun | None:
        """The rules' binary run (made once per rule set), None if they have none."""
        rule = binary_rule(rules)
        if isinstance(rule, str):
            return None
        run = rules._tables.get("hashlife_bits_run")
        if run is None:
            run = cls(BitStore(limit_bytes=memory), rule)
            rules._tables["hashlife_bits_run"] = run
        run.store.limit_bytes = int(memory)
        return run

    def tree(self, node: int) -> BitTree:
        """The tree an engine adopts; the store renumbers it if it collects garbage later
        (another engine of these rules may hold its state only in a tree)."""
        tree = BitTree(self.store, self.store.epoch, node)
        self.store.trees.add(tree)
        return tree

    def plane(self, engine) -> int:  # an Engine
        """The engine's plane as a node: its tree if that is ours and valid, else built
        from its cells (all 1s)."""
        tree = engine.tree
        if isinstance(tree, BitTree) and tree.valid(self.store):
            return tree.node
        window = engine.dense_window
        s = self.store
        collected = False
        while True:  # a dense plane may need the tables doubled several times
            node = (convert.grid_to_tree(window[0], window[1], window[2], s)
                    if window is not None else convert.to_tree(engine.xs, engine.ys, s))
            if node >= 0:
                return node
            if s.grow_if_full():
                continue
            if collected:
                break
            collected = True
            s.make_room([])
        raise MemoryError("the plane does not fit the HashLife memory limit "
                          f"({s.limit_bytes >> 20} MB)")

    def jump(self, node: int, generations: int, edges: str) -> int:
        """The plane ``node`` after ``generations`` (1..MAX_JUMP); on a full table grow it
        (within the memory limit) or collect garbage and retry, as a last resort two jumps
        of half the length."""
        s = self.store
        collected = False
        while True:
            try:
                out = evolve.advance(frame(s, node, edges), generations, s, self.rule.packed,
                                     self.grids)
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
        return self.jump(self.jump(node, first, edges), generations - first, edges)
