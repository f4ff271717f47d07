"""What both leaf strategies' runs share: a rule set's store, its rules packed for the leaf
kernel and the kernel's scratch, and the questions answered the same way for either kind of
leaf (one jump, the census, the cell list)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.ca.hashlife import census, evolve, listing
from camlab88.apps.ca.hashlife.store import Store


@dataclass(eq=False)
class StoreRun:
    store: Store
    rules: np.ndarray  # uint64: the leaf kernel's packed rules
    scratch: np.ndarray  # uint64, 2-d: the leaf kernel's work space

    def advance(self, framed: int, generations: int) -> int:
        """The centre of the framed plane after ``generations``; -1 if a table filled."""
        return evolve.advance(framed, generations, self.store, self.rules, self.scratch)

    def population(self, node: int) -> int:
        return census.cells_of(node, 0, self.store)

    def by_type(self, node: int, forms: int) -> dict[int, int]:
        return census.by_type(node, forms, self.store)

    def occupied(self, node: int, axis: int) -> np.ndarray:
        return census.occupied(node, axis, self.store)

    def cells(self, node: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return listing.cells(node, self.store)
