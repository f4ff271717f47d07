"""Every HashLife kernel called once, with the argument types real runs use.

The completions of HashLife's kernel groups (base.kernel_notice), one per group: after the
first cold compile of a group the rest of that group compiles, so its notice is printed
once per install.  The groups (apps/ca/hashlife/__init__.py): what every jump needs (store,
census, a tree's levels), each kind of leaf with the recursion compiled for it, the cell
lists in, the cells listed out, the tables' growth and collection.  Each completion calls
only its own group's kernels where it can (or kernels every run of that kind has compiled
before it), so a first run's exit compiles nothing of a group it did not touch: Life's
first run compiles neither the value leaves nor the cell lists, a multi-state run's not the
bit leaves.  ``compile_kernels`` (``camlab88 warm-up``) compiles every group.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import numpy as np

from camlab88.apps.ca.engine import CENTRE, Engine
from camlab88.apps.ca.hashlife import cells, census, listing
from camlab88.apps.ca.hashlife.kernels import (
    BIT_LEAF_LEVEL,
    LEAF_TABLE,
    NODE_TABLE,
    PLANE_LEVEL,
    rehash,
)
from camlab88.apps.ca.hashlife.store import Store
from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules

_STORES = ((0, 2), (BIT_LEAF_LEVEL, BIT_LEAF_LEVEL + 1))  # (leaf, base) of each kind


def compile_kernels() -> None:
    """Every group (``camlab88 warm-up``)."""
    compile_common()
    compile_bits()
    compile_values()
    compile_cells()
    compile_listing()
    compile_upkeep()


def compile_common() -> None:
    """What every jump needs, on an empty plane of each kind of store: the census and the
    tables' towers (made with the store); a tree's levels are compiled inside the
    conversions that build trees."""
    for leaf, base in _STORES:
        store = Store(leaf, base, 0, 1)
        plane = int(store.empty[PLANE_LEVEL])
        census.cells_of(plane, 0, store)
        census.occupied(plane, 0, store)


def compile_bits() -> None:
    """Bit leaves' jumps (Life, from the pattern's grid as `ca run` places it), both edges."""
    placed = read_pattern(pattern_path("gosper_gun")).placed_grid(CENTRE, CENTRE, "identity")
    _jumps("life", lambda engine: engine.set_grid(*placed), 300)


def compile_values() -> None:
    """Value leaves' jumps (a multi-state rule set; its cells by the cell lists, which
    every such run compiles first), both edges."""
    placed = read_pattern(pattern_path("primes_25")).placed(CENTRE, CENTRE, "identity")
    _jumps("turing_primes", lambda engine: engine.set_cells(*placed), 64)


def _jumps(rules_name: str, place: Callable[[Engine], object], generations: int) -> None:
    """A HashLife jump and its census on each kind of edge."""
    rules = load_rules(rules_path(rules_name))
    for edges in ("wrap", "bounded"):
        engine = Engine(rules, edges=edges, algorithm="hashlife")
        place(engine)
        engine.step(generations)
        engine.stats()


def compile_cells() -> None:
    """The cell lists in, for both kinds of leaf, and the seam test (a multi-state run on
    the wrapping plane)."""
    for store, node in _two_cell_planes():
        cells.near_seam(node, 1, store)


def compile_listing() -> None:
    """The cells of a plane listed, for both kinds of leaf."""
    for store, node in _two_cell_planes():
        listing.cells(node, store)


def _two_cell_planes() -> Iterator[tuple[Store, int]]:
    """A store of each kind of leaf and a plane of two cells in it (by the cell lists)."""
    for leaf, base in _STORES:
        store = Store(leaf, base, 0, 1)
        xs = ys = np.array([5, 40000], np.int64)
        yield store, cells.to_tree(xs, ys, np.ones(2, np.int64), store)


def compile_upkeep() -> None:
    """The tables' growth and collection (their group's completion)."""
    store = Store(4, 5, 0, 1)
    store.make_room([])
    store.slots[:] = 0  # as grow_if_full does after growing: every entry hashed again
    store.lslots[:] = 0
    rehash(NODE_TABLE | LEAF_TABLE, *store.tables)
