"""Every HashLife kernel called once, with the argument types real runs use.

The completions of the "binary HashLife" and "HashLife" kernel groups (base.kernel_notice),
one per group: after the first cold compile of a group, the rest of that group compiles
(both edge modes, the collector, growth, the cell lists), so its notice is printed once per
install. Life's first run compiles the binary group alone (about half the time of both);
a rule set of more life-forms (the Turing machine, the maze, the circuits) compiles the
generic group, under its own notice, the first time one runs. Short runs through the
engine itself, on both edge modes. ``compile_kernels`` (``camlab88 warm-up``) does both.
"""

from __future__ import annotations

import numpy as np

from apps.ca.engine import CENTRE, Engine
from apps.ca.hashlife import convert
from apps.ca.hashlife.bits import convert as bit_convert
from apps.ca.hashlife.bits.store import EMPTY, BitStore
from apps.ca.hashlife.bits.store import rehash as bit_rehash
from apps.ca.hashlife.store import NodeStore
from apps.ca.library import pattern_path, rules_path
from apps.ca.patterns import read_pattern
from apps.ca.rules import load_rules

BINARY_RUN = ("life", "gosper_gun")
GENERIC_RUN = ("turing_primes", "primes_25")


def compile_kernels() -> None:
    """Both groups (``camlab88 warm-up``)."""
    compile_binary()
    compile_generic()


def compile_binary() -> None:
    """The binary group's completion."""
    _runs(*BINARY_RUN)
    _bit_tables()


def compile_generic() -> None:
    """The generic group's completion."""
    _runs(*GENERIC_RUN)
    _generic_tables()


def _runs(rules_name: str, pattern_name: str) -> None:
    rules = load_rules(rules_path(rules_name))
    xs, ys, ts = read_pattern(pattern_path(pattern_name)).placed(CENTRE, CENTRE, "identity")
    for edges in ("wrap", "bounded"):
        engine = Engine(rules, edges=edges, algorithm="hashlife")
        engine.set_cells(xs, ys, ts)
        engine.step(300)
        engine.stats()
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


def _bit_tables() -> None:
    """The same on the binary tables."""
    bits = BitStore()
    bit_convert.cells(np.int64(bits.meta[EMPTY + bit_convert.PLANE_LEVEL]), bits.nodes,
                      bits.leaves, bits.meta)
    bits.make_room([])
    bits.slots[:] = 0  # as grow_if_full does after doubling: every entry hashed again
    bits.lslots[:] = 0
    bit_rehash(bits.nodes, bits.slots, bits.leaves, bits.lslots, bits.meta)
