"""The engine holds exactly one universe — a cell list, a dense grid or a HashLife tree —
in the form of the algorithm that last stepped it; reading never converts it, editing turns
it into a cell list, and the other forms are never kept beside it."""

from __future__ import annotations

import numpy as np

from camlab88.apps.ca.engine import CENTRE, Engine
from camlab88.apps.ca.hashlife.tree import Tree
from camlab88.apps.ca.library import rules_path
from camlab88.apps.ca.rules import load_rules
from camlab88.apps.ca.universe import CellList, DenseGrid

LIFE = load_rules(rules_path("life"))
MAZE = load_rules(rules_path("maze"))


def _soup(side: int, seed: int) -> np.ndarray:
    return (np.random.default_rng(seed).random((side, side)) < 0.45).astype(np.uint8)


def test_a_jump_leaves_one_tree_that_reading_keeps_and_editing_replaces() -> None:
    e = Engine(LIFE, algorithm="hashlife")
    ys, xs = np.nonzero(_soup(40, 1))
    e.set_cells(xs + CENTRE, ys + CENTRE, 1)
    assert isinstance(e.universe, CellList)
    e.step(100)
    tree = e.universe
    assert isinstance(tree, Tree) and e.tree is tree
    before = e.stats()
    e.cells()
    e.get(CENTRE, CENTRE)
    e.cells_in_rect(e.bbox())
    assert e.universe is tree  # looked at, not converted: the next jump starts from it
    ref = Engine(LIFE, algorithm="direct")
    ref.set_cells(xs + CENTRE, ys + CENTRE, 1)
    ref.step(100)
    assert e.same_state(ref) and ref.stats() == before
    e.set(0, 0, 1)
    assert isinstance(e.universe, CellList) and e.tree is None
    assert e.population == before["population"] + 1


def test_a_dense_grid_stays_the_universe_while_it_is_read() -> None:
    grid = _soup(200, 2)
    e = Engine(LIFE, algorithm="direct")
    e.set_grid(1000, 2000, grid)
    e.step(2)
    window = e.universe
    assert isinstance(window, DenseGrid)
    xs, ys, ts = e.cells()
    assert e.universe is window and e.population == xs.size == int(ts.sum())
    copy = e.copy()  # the copy gets a list of its own; the original keeps its grid
    assert isinstance(copy.universe, CellList) and e.universe is window
    e.step(3)
    copy.step(3)
    assert e.same_state(copy)


def test_changing_rules_drops_a_tree_of_the_old_rules() -> None:
    e = Engine(LIFE, algorithm="hashlife")
    ys, xs = np.nonzero(_soup(30, 3))
    e.set_cells(xs + CENTRE, ys + CENTRE, 1)
    e.step(64)
    assert e.tree is not None
    cells = e.cells()
    e.set_rules(MAZE)
    assert e.tree is None and isinstance(e.universe, CellList)
    assert all(np.array_equal(a, b) for a, b in zip(cells, e.cells()))
