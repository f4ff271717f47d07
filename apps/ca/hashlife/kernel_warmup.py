"""Every HashLife kernel called once, with the argument types real runs use.

The completions of HashLife's kernel groups (base.kernel_notice), one per group: after the
first cold compile of a group the rest of that group compiles, so its notice is printed
once per install.  Three groups, for either kind of leaf (one store, one recursion: the
same compiled kernels serve both): the jumps (with the census and the dense window's
conversion: all a `ca run --json` of a small Life pattern needs), the cell lists (pictures,
sparse patterns, any multi-state run) and the tables' growth and collection (runs that fill
them).  So Life's first run compiles neither the cell lists nor the collector.  Short runs
through the engine itself, on both edge modes.  ``compile_kernels`` (``camlab88 warm-up``)
compiles every group.
"""

from __future__ import annotations

import numpy as np

from apps.ca.engine import CENTRE, Engine
from apps.ca.hashlife import cells
from apps.ca.hashlife.generic import GenericRun
from apps.ca.hashlife.store import Store
from apps.ca.library import pattern_path, rules_path
from apps.ca.patterns import read_pattern
from apps.ca.rules import load_rules


def compile_kernels() -> None:
    """Every group (``camlab88 warm-up``)."""
    compile_jumps()
    compile_cells()
    compile_upkeep()


def compile_jumps() -> None:
    """The jumps' completion: jumps, census, the dense window's conversion (Life, from the
    pattern's grid as `ca run` places it)."""
    rules = load_rules(rules_path("life"))
    grid = read_pattern(pattern_path("gosper_gun")).placed_grid(CENTRE, CENTRE, "identity")
    for edges in ("wrap", "bounded"):
        engine = Engine(rules, edges=edges, algorithm="hashlife")
        engine.set_grid(*grid)
        engine.step(300)
        engine.stats()


def compile_cells() -> None:
    """The cell lists' completion: cells to a tree and back for both kinds of leaf, and
    the seam test (a multi-state run on the wrapping plane)."""
    rules = load_rules(rules_path("turing_primes"))
    xs, ys, ts = read_pattern(pattern_path("primes_25")).placed(CENTRE, CENTRE, "identity")
    engine = Engine(rules, algorithm="hashlife")
    engine.set_cells(xs, ys, ts)
    engine.step(2)
    engine.cells()
    store = GenericRun.of(rules, engine.hashlife_memory).store
    cells.near_seam(int(store.empty[16]), 1, store)
    bits = Store(4, 5, 0, 1)
    xs = ys = np.array([5, 40000], np.int64)
    cells.cells(cells.to_tree(xs, ys, np.ones(2, np.int64), bits), bits)


def compile_upkeep() -> None:
    """The tables' growth and collection (their group's completion)."""
    store = Store(4, 5, 0, 1)
    store.make_room([])
    store.slots[:] = 0  # as grow_if_full does after doubling: every entry hashed again
    store.lslots[:] = 0
    from apps.ca.hashlife.upkeep import rehash

    rehash(*store.tables)
