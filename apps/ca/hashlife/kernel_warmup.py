"""Every HashLife kernel called once, with the argument types real runs use.

The completion of the "HashLife" and "binary HashLife" kernel groups
(base.kernel_notice): after the first cold compile of either, both compile, so Life
(the binary path, which also uses the generic tree's conversions) and a later rule set of
more life-forms (the generic path: the Turing machine, the maze, the circuits) share one
compile. Short runs through the engine itself, on both edge modes, with a node-table limit
small enough to make the garbage collector run.
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

RUNS = (("life", "gosper_gun"), ("turing_primes", "primes_25"))


def compile_kernels() -> None:
    for rules_name, pattern_name in RUNS:
        rules = load_rules(rules_path(rules_name))
        xs, ys, ts = read_pattern(pattern_path(pattern_name)).placed(CENTRE, CENTRE,
                                                                     "identity")
        for edges in ("wrap", "bounded"):
            engine = Engine(rules, edges=edges, algorithm="hashlife")
            engine.set_cells(xs, ys, ts)
            engine.step(300)
            engine.stats()
            engine.cells()
    _tables()


def _tables() -> None:
    """Growth, collection and the cell lists of empty planes, on both kinds of table."""
    generic = NodeStore()
    top = int(convert.PLANE_LEVEL)
    plane = np.int64(generic.empty[top])
    convert.cells(plane, generic.nodes, generic.empty)
    convert.near_seam(int(plane), 1, generic.nodes, generic.empty)
    generic.make_room([])
    generic._grow()  # the rehash kernel, as a growing run calls it
    bits = BitStore()
    bit_convert.cells(np.int64(bits.meta[EMPTY + bit_convert.PLANE_LEVEL]), bits.nodes,
                      bits.leaves, bits.meta)
    bits.make_room([])
    bits.slots[:] = 0  # as grow_if_full does after doubling: every entry hashed again
    bits.lslots[:] = 0
    bit_rehash(bits.nodes, bits.slots, bits.leaves, bits.lslots, bits.meta)
