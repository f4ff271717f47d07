"""HashLife's binary leaf strategy: two-state rules on a plane of 1s, 16 x 16-cell leaves
of bits, jumps of any length up to MAX_JUMP in one pass (the store, the recursion, the
tree, its jumps and their memory handling are shared with the generic strategy)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.ca.hashlife import cells
from camlab88.apps.ca.hashlife.bits.rule import BinaryRule, binary_rule
from camlab88.apps.ca.hashlife.bits.window import grid_to_tree
from camlab88.apps.ca.hashlife.kernels import BIT_LEAF_LEVEL, PLANES
from camlab88.apps.ca.hashlife.run import StoreRun
from camlab88.apps.ca.hashlife.store import Store
from camlab88.apps.ca.rules import RuleSet

MAX_JUMP = 1 << 15  # generations: the level-17 frame's centre after at most 2**15


@dataclass(eq=False)
class BitRun(StoreRun):
    """What one binary rule's jumps need: its tables, its kernel table and scratch rows."""

    rule: BinaryRule | None = None

    @classmethod
    def of(cls, rules: RuleSet, memory: int) -> BitRun | None:
        """The rules' binary run (made once per rule set), None if they have none."""
        rule = binary_rule(rules)
        if isinstance(rule, str):
            return None
        run = rules._tables.get("hashlife_bits_run")
        if run is None:
            store = Store(BIT_LEAF_LEVEL, BIT_LEAF_LEVEL + 1, 0, 1, limit_bytes=memory)
            run = cls(store, rule.packed, np.zeros((PLANES, 32), np.uint64), rule)
            rules._tables["hashlife_bits_run"] = run
        run.store.limit_bytes = int(memory)
        return run

    def build(self, engine) -> int:
        """The engine's plane (all 1s) from its dense window or its cells."""
        window = engine.dense_window
        if window is not None:
            return grid_to_tree(window[0], window[1], window[2], self.store)
        return cells.to_tree(engine.xs, engine.ys, engine.ts, self.store)

    def next_jump(self, node: int, remaining: int, edges: str) -> int:
        return min(MAX_JUMP, remaining)
