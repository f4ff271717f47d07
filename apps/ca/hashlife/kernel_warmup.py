"""Every HashLife kernel called once, with the argument types real runs use.

The completions of HashLife's kernel groups (base.kernel_notice), one per group: after the
first cold compile of a group the rest of that group compiles, so its notice is printed
once per install. The binary path (Life) is three groups: the jumps (with the census and
the dense window's conversion: all a `ca run --json` of a small pattern needs), the cell
lists (pictures, sparse patterns) and the tables' growth and collection (runs that fill
them); the generic path (the Turing machine, the maze, the circuits) is one. So Life's
first run compiles neither the generic recursion nor what it does not use. Short runs
through the engine itself, on both edge modes. ``compile_kernels`` (``camlab88 warm-up``)
compiles every group.
"""

from __future__ import annotations

import numpy as np

from apps.ca.engine import CENTRE, Engine
from apps.ca.hashlife import convert
from apps.ca.hashlife.bits import cells as bit_cells
from apps.ca.hashlife.bits.collect import rehash as bit_rehash
from apps.ca.hashlife.bits.store import BitStore
from apps.ca.hashlife.store import NodeStore
from apps.ca.library import pattern_path, rules_path
from apps.ca.patterns import read_pattern
from apps.ca.rules import load_rules

BINARY_RUN = ("life", "gosper_gun")
GENERIC_RUN = ("turing_primes", "primes_25")


def compile_kernels() -> None:
    """Every group (``camlab88 warm-up``)."""
    compile_binary()
    compile_bit_cells()
    compile_bit_upkeep()
    compile_generic()


def compile_binary() -> None:
    """The binary group's completion: jumps, census, the dense window's conversion."""
    _runs(*BINARY_RUN, cells=False)


def compile_bit_cells() -> None:
    """The binary cell lists' completion: cells to a tree and back."""
    store = BitStore()
    xs = ys = np.array([5, 40000], np.int64)
    bit_cells.cells(np.int64(bit_cells.to_tree(xs, ys, store)), store.nodes, store.leaves,
                    store.meta)


def compile_bit_upkeep() -> None:
    """The binary tables' growth and collection (their group's completion)."""
    bits = BitStore()
    bits.make_room([])
    bits.slots[:] = 0  # as grow_if_full does after doubling: every entry hashed again
    bits.lslots[:] = 0
    bit_rehash(bits.nodes, bits.slots, bits.leaves, bits.lslots, bits.meta)


def compile_generic() -> None:
    """The generic group's completion."""
    _runs(*GENERIC_RUN)
    _generic_tables()


def _runs(rules_name: str, pattern_name: str, cells: bool = True) -> None:
    """Jumps from the pattern as `ca run` places it (a dense pattern from its grid)."""
    rules = load_rules(rules_path(rules_name))
    pattern = read_pattern(pattern_path(pattern_name))
    grid = pattern.placed_grid(CENTRE, CENTRE, "identity")
    cells = pattern.placed(CENTRE, CENTRE, "identity") if grid is None else None
    for edges in ("wrap", "bounded"):
        engine = Engine(rules, edges=edges, algorithm="hashlife")
        engine.set_grid(*grid) if grid is not None else engine.set_cells(*cells)
        engine.step(300)
        engine.stats()
        if cells:
            engine.cells()


def _generic_tables() -> None:
    """Growth, collection and the cell lists of an empty plane, on the generic table."""
    generic = NodeStore()
    top = int(convert.PLANE_LEVEL)
    plane = np.int64(generic.empty[top])
    convert.cells(plane, generic.nodes, generic.empty)
    convert.near_seam(int(plane), 1, generic.nodes, generic.empty)
    generic.make_room([])
    generic._grow()  # the rehash kernel, as a growing run calls it
