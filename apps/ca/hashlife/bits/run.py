"""HashLife's binary leaf strategy: two-state rules on a plane of 1s, 16 x 16-cell leaves
of bits, jumps of any length up to MAX_JUMP in one pass (the tree, its jumps and their
memory handling are ../tree.py's, shared with the generic strategy)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from apps.ca.hashlife.bits import cells, census, convert, evolve
from apps.ca.hashlife.bits.leaves import PLANES
from apps.ca.hashlife.bits.rule import BinaryRule, binary_rule
from apps.ca.hashlife.bits.store import BitStore
from apps.ca.rules import RuleSet

MAX_JUMP = 1 << 15  # generations: the level-17 frame's centre after at most 2**15


@dataclass(eq=False)
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

    def build(self, engine) -> int:
        """The engine's plane (all 1s) from its dense window or its cells."""
        window = engine.dense_window
        if window is not None:
            return convert.grid_to_tree(window[0], window[1], window[2], self.store)
        return cells.to_tree(engine.xs, engine.ys, self.store)

    def next_jump(self, node: int, remaining: int, edges: str) -> int:
        return min(MAX_JUMP, remaining)

    def advance(self, framed: int, generations: int) -> int:
        return evolve.advance(framed, generations, self.store, self.rule.packed, self.grids)

    def population(self, node: int) -> int:
        return census.count(node, self.store)

    def by_type(self, node: int, forms: int) -> dict[int, int]:
        """{1: cells} (empty if none): a binary plane has only 1s."""
        n = self.population(node)
        return {1: n} if n else {}

    def occupied(self, node: int, axis: int) -> np.ndarray:
        return census.occupied(node, axis, self.store)

    def cells(self, node: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        s = self.store
        rows = cells.cells(np.int64(node), s.nodes, s.leaves, s.meta)
        return rows[:, 0].copy(), rows[:, 1].copy(), np.ones(rows.shape[0], np.int64)
