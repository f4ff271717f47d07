"""HashLife's generic leaf strategy: leaves are single cells holding life-form values (any
deterministic rule set, any reach), the base case runs the rules on a small grid
(``cellgrid``), jumps are powers of two.

Order-dependent rules on the wrapping plane keep live cells away from the seam (where the
direct engine's absolute order of senders is not the order relative to the receiver): the
next jump is the longest whose messages cannot reach it, 0 (step directly) if none.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.ca.hashlife import cells
from camlab88.apps.ca.hashlife.leaf import order_matters, pack
from camlab88.apps.ca.hashlife.run import StoreRun
from camlab88.apps.ca.hashlife.store import SHIFT, TOP_LEVEL, Store
from camlab88.apps.ca.rules import RuleSet

# Leaves are this many levels above the smallest possible (2**(s+2) cells square, one
# generation): bigger leaves run more generations directly per memoised result.
LEAF_EXTRA = 0
# The table's first size and its smallest (a large empty table costs nothing up front:
# its pages stay untouched until used).
NODES, MIN_NODES = 1 << 20, 1 << 16


@dataclass(eq=False)
class GenericRun(StoreRun):
    """What one rule set's jumps need: its node table, packed rules and scratch grids."""

    reach: int = 1
    order_matters: bool = False
    forms: int = 1  # the largest life-form the rules name

    @classmethod
    def of(cls, rules: RuleSet, memory: int) -> GenericRun:
        """The rules' generic run (made once per rule set)."""
        run = rules._tables.get("hashlife_run")
        if run is None:
            ry, rx = rules.reach
            reach = max(ry, rx, 1)
            shift = (reach - 1).bit_length()  # 2**shift >= the reach
            base = shift + 2 + LEAF_EXTRA
            store = Store(0, base, shift, reach, limit_bytes=memory, nodes=NODES,
                          min_nodes=MIN_NODES)
            run = cls(store, pack(rules).view(np.uint64),
                      np.zeros((4 << base, 1 << base), np.uint64), reach,
                      order_matters(rules), rules.max_form)
            rules._tables["hashlife_run"] = run
        run.store.limit_bytes = int(memory)
        return run

    @property
    def max_j(self) -> int:
        return TOP_LEVEL - 2 - int(self.store.meta[SHIFT])

    def build(self, engine) -> int:
        return cells.to_tree(engine.xs, engine.ys, engine.ts, self.store)

    def next_jump(self, node: int, remaining: int, edges: str) -> int:
        j = min(self.max_j, remaining.bit_length() - 1)
        if edges == "wrap" and self.order_matters:
            while j >= 0 and cells.near_seam(node, self.reach * ((1 << j) + 1), self.store):
                j -= 1
        return 0 if j < 0 else 1 << j
