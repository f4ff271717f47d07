"""HashLife's generic leaf strategy: leaves are single cells holding life-form values (any
deterministic rule set, any reach), the base case runs the rules on a small grid
(``leaf.generation``), jumps are powers of two (``evolve``).

Order-dependent rules on the wrapping plane keep live cells away from the seam (where the
direct engine's absolute order of senders is not the order relative to the receiver): the
next jump is the longest whose messages cannot reach it, 0 (step directly) if none.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from apps.ca.hashlife import census, convert, evolve
from apps.ca.hashlife.leaf import order_matters, pack
from apps.ca.hashlife.store import TOP_LEVEL, NodeStore
from apps.ca.rules import RuleSet

# Leaves are this many levels above the smallest possible (2**(s+2) cells square, one
# generation): bigger leaves run more generations directly per memoised result.
LEAF_EXTRA = 0


@dataclass(eq=False)
class GenericRun:
    """What one rule set's jumps need: its node table and packed rules."""

    store: NodeStore
    packed: np.ndarray
    params: np.ndarray  # int64 (leaf level, s, reach)
    grids: np.ndarray  # the leaf's scratch grids: cells, next cells, node ids, messages
    order_matters: bool
    forms: int  # the largest life-form the rules name

    @classmethod
    def of(cls, rules: RuleSet, memory: int) -> GenericRun:
        """The rules' generic run (made once per rule set)."""
        run = rules._tables.get("hashlife_run")
        if run is None:
            ry, rx = rules.reach
            reach = max(ry, rx, 1)
            shift = (reach - 1).bit_length()  # 2**shift >= the reach
            leaf = shift + 2 + LEAF_EXTRA
            run = cls(NodeStore(limit_bytes=memory), pack(rules),
                      np.array([leaf, shift, reach], np.int64),
                      np.zeros((4, 1 << leaf, 1 << leaf), np.int64), order_matters(rules),
                      rules.max_form)
            rules._tables["hashlife_run"] = run
        run.store.limit_bytes = int(memory)
        return run

    @property
    def max_j(self) -> int:
        return TOP_LEVEL - 2 - int(self.params[1])

    def build(self, engine) -> int:
        ys, xs, ts = engine.ys, engine.xs, engine.ts
        keys = convert.morton(xs, ys)
        order = np.argsort(keys)
        s = self.store
        return int(convert.build(keys[order], ts[order], s.nodes, s.slots, s.meta, s.empty))

    def next_jump(self, node: int, remaining: int, edges: str) -> int:
        j = min(self.max_j, remaining.bit_length() - 1)
        if edges == "wrap" and self.order_matters:
            r = int(self.params[2])
            s = self.store
            while j >= 0 and convert.near_seam(node, r * ((1 << j) + 1), s.nodes, s.empty):
                j -= 1
        return 0 if j < 0 else 1 << j

    def advance(self, framed: int, generations: int) -> int:
        j = generations.bit_length() - 1  # a power of two (next_jump's, or half of one)
        return evolve.advance(framed, j, self.params, self.store, self.packed, self.grids)

    def population(self, node: int) -> int:
        return sum(self.by_type(node, self.forms).values())

    def by_type(self, node: int, forms: int) -> dict[int, int]:
        s = self.store
        return census.counts(node, forms, s.nodes, s.count)

    def occupied(self, node: int, axis: int) -> np.ndarray:
        s = self.store
        return census.occupied(node, axis, s.nodes, s.empty, s.count)

    def cells(self, node: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        rows = convert.cells(np.int64(node), self.store.nodes, self.store.empty)
        return rows[:, 0].copy(), rows[:, 1].copy(), rows[:, 2].copy()
