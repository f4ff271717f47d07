"""The memoised HashLife recursion (Gosper 1984), once for both kinds of leaf.

With 2**s at least the rules' message reach, a node of level k knows its centre after T
generations for any T <= 2**(k-2-s): the light cone stays inside the 2**(k-2) margin.  The
four squares built from the nine overlapping sub-squares' results advance
t2 = min(T, 2**(k-3-s)) generations, the nine the rest, T - t2 (none: their centres as they
are).  At full speed (T = 2**(k-2-s)) that is Gosper's; any other T costs one pass too,
where jumps of powers of two would take one pass per binary digit.  The memo keeps one T
per node besides the full-speed result.  Nodes of the base level run the leaf kernel
directly: ``advance_bits`` (binary rules: four 16 x 16 bit leaves, up to 8 generations by
bit operations) or ``advance_values`` (any rules: the rules on a grid of life-form values).
The recursion is compiled once per kind of leaf, each copy calling its own leaf kernel
(``step_bits``, ``step_values``), so a
run compiles its own leaf kernel only (a run-time branch compiled both: 2 s more of a first
run's compile).  Every kernel returns -1 when a table is full.  The kernels are in
``kernels`` (apps/ca/hashlife/kernels.py), with every other HashLife kernel.

Written for numba's costs as measured: compiled without numba's runtime (``_nrt=False``:
nothing here allocates), so array arguments are not atomically reference counted per call
(that was half the time of small jumps); the tables passed as arrays (nine; their
addresses in one array took 3 arguments, not 57, and were 5-10 % faster, but built arrays
owning nothing inside the kernels: docs/perf/ca.md); self-recursive only (a cached mutually
recursive pair crashed the next process); the nine and four squares in a frame per level
in ``meta`` (no heap allocation per call, no indexed tuple); unsigned indices where numba
would test for negative ones; memoised results looked up before calling.  The module
belongs to no kernel group: its kernels compile only inside a kind's entry, whose leaf
kernel's group announces the compile.
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.ca.hashlife.kernels import (
    step_bits,
    step_values,
)


def advance(node: int, T: int, store, R: np.ndarray, G: np.ndarray) -> int:  # a Store
    """The centre of ``node`` after T generations (-1: a table filled up)."""
    step = step_bits if store.leaf_level else step_values
    return int(step(np.int64(node), np.int64(T), *store.tables, R, G))
