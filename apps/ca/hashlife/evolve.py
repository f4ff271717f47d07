"""The memoised HashLife recursion (Gosper 1984), once for both kinds of leaf.

With 2**s at least the rules' message reach, a node of level k knows its centre after T
generations for any T <= 2**(k-2-s): the light cone stays inside the 2**(k-2) margin.  The
four squares built from the nine overlapping sub-squares' results advance
t2 = min(T, 2**(k-3-s)) generations, the nine the rest, T - t2 (none: their centres as they
are).  At full speed (T = 2**(k-2-s)) that is Gosper's; any other T costs one pass too,
where jumps of powers of two would take one pass per binary digit.  The memo keeps one T
per node besides the full-speed result.  Nodes of the base level run the leaf kernel
directly: ``bits.leaves`` (binary rules: four 16 x 16 bit leaves, up to 8 generations by
bit operations) or ``cellgrid`` (any rules: the rules on a grid of life-form values).
Which one is chosen by type when a kind's entry
compiles (value leaves have no leaf table: their entry passes None for it), so a run
compiles its own leaf kernel only (a run-time branch compiled both: 2 s more of a first
run's compile).  Every kernel returns -1 when a table is full.

Written for numba's costs as measured: compiled without numba's runtime (``_nrt=False``:
nothing here allocates), so array arguments are not atomically reference counted per call
(that was half the time of small jumps); the tables handed on by address, not as arrays
(base/raw_views.py: 3 arguments a call, not 57); self-recursive only (a cached mutually
recursive pair crashed the next process); the nine and four squares in a frame per level
in ``meta`` (no heap allocation per call, no indexed tuple); unsigned indices where numba
would test for negative ones; memoised results looked up before calling.  The module
belongs to no kernel group: its kernels compile only inside a kind's entry, whose leaf
kernel's group announces the compile.
"""

from __future__ import annotations

import numpy as np
from camlab88.apps.ca.hashlife import cellgrid
from camlab88.apps.ca.hashlife.bits import leaves as bitleaves
from camlab88.apps.ca.hashlife.store import (
    BASE,
    EMPTY,
    FRAME,
    FRAMES,
    FULL,
    LEAF,
    LEVEL,
    RES,
    RESJ,
    SHIFT,
    TABLES,
    WALL_AT,
    join,
    node_tables,
    publish,
)
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__, sources=(
    "camlab88.apps.ca.hashlife.bits.leaves",
    "camlab88.apps.ca.hashlife.cellgrid",
    "camlab88.apps.ca.hashlife.leaf",
    "camlab88.apps.ca.hashlife.store",
    "camlab88.base.raw_views",
    "camlab88.base.raw_view_intrinsics",
))

RULES, SCRATCH = "uint64[::1]", "uint64[:, ::1]"


@kernels.kernel(inline="always")
def _q(nodes, n, q):
    return np.int64(nodes[np.uint64(n), q])  # unsigned: no test for a negative index


@kernels.kernel(inline="always")
def _centre(n, h, nodes, slots, meta):
    """The centre half of ``n`` (of level h > the leaves' + 1; no time passes); -1 if a
    table is full."""
    return join(_q(nodes, _q(nodes, n, 0), 3), _q(nodes, _q(nodes, n, 1), 2),
                _q(nodes, _q(nodes, n, 2), 1), _q(nodes, _q(nodes, n, 3), 0), h - 1, nodes,
                slots, meta)


@kernels.kernel(inline="always")
def _known(n, T, level, nodes, meta):
    """The result of ``n`` (of ``level``) for T generations if it is known without
    recursing — an empty or wall node's, or memoised — else -2 (-1: n is -1)."""
    if n < 0:
        return n
    e, w = np.uint64(EMPTY + level), np.uint64(WALL_AT + level)  # unsigned: no tests for
    if n == meta[e]:  # negative indices
        return meta[e - np.uint64(1)]
    if n == meta[w]:
        return meta[w - np.uint64(1)]
    u = np.uint64(n)
    if T == np.int64(1) << (level - 2 - meta[SHIFT]):
        if nodes[u, FULL] > 0:
            return np.int64(nodes[u, FULL])
    elif nodes[u, RESJ] == T + 1:
        return np.int64(nodes[u, RES])
    return np.int64(-2)


def _leaf_step(node, T, at):
    """The leaf kernel each specialisation of ``_recursion`` binds in its place
    (``bits.leaves.advance`` or ``cellgrid.advance``): the centre of base-level ``node``
    after T generations (0: its centre as it is); ``at``: the tables' addresses."""
    raise NotImplementedError("bound per kind of leaf by kernels.specialise")


# _nrt=False: the recursion allocates nothing, and without numba's runtime its array
# arguments are not reference counted — perf showed those atomic counts taking half the time
# of small jumps (gun 1.6 -> 0.7 ms, spacefiller 1.7 -> 0.8, puffer 95 -> 77).  A template,
# compiled once per kind of leaf as that kind's export (below), ``_leaf_step`` bound to its
# leaf kernel.
def _recursion(node, T, at):
    """Centre of ``node`` after T generations (1 <= T <= 2**(level - 2 - s)); -1 if a table
    is full.  ``at``: the address of the store's meta holding the tables' addresses
    (``_entry``): three arguments a call instead of 57 (9 arrays, base/raw_views.py)."""
    nodes, slots, meta = node_tables(at)
    k = np.int64(nodes[np.uint64(node), LEVEL])
    found = _known(node, T, k, nodes, meta)  # (the recursion's callers looked already:
    if found != -2:  # this is for the first call, saving Python a kernel of its own)
        return found
    if k == meta[BASE]:
        out = _leaf_step(node, T, at)
    else:
        h = k - 1
        t2 = min(T, np.int64(1) << (k - 3 - meta[SHIFT]))  # the four's: full speed if it can
        t1 = T - t2  # the nine's (0: their centres as they are)
        a, b, c, d = _q(nodes, node, 0), _q(nodes, node, 1), _q(nodes, node, 2), \
            _q(nodes, node, 3)
        # The nine, row by row, in this level's frame: 0..8, their results 9..17, the four
        # 18..21, theirs 22..25.  (A tuple indexed in the loop cost two indirect jumps an
        # iteration: LLVM does not unroll a loop around a recursive call.)
        f = FRAMES + FRAME * k
        fr = meta[f:f + FRAME]  # (a view: indices known >= 0, no negative-index tests)
        fr[0] = a
        fr[1] = join(_q(nodes, a, 1), _q(nodes, b, 0), _q(nodes, a, 3), _q(nodes, b, 2), h,
                     nodes, slots, meta)
        fr[2] = b
        fr[3] = join(_q(nodes, a, 2), _q(nodes, a, 3), _q(nodes, c, 0), _q(nodes, c, 1), h,
                     nodes, slots, meta)
        fr[4] = join(_q(nodes, a, 3), _q(nodes, b, 2), _q(nodes, c, 1), _q(nodes, d, 0), h,
                     nodes, slots, meta)
        fr[5] = join(_q(nodes, b, 2), _q(nodes, b, 3), _q(nodes, d, 0), _q(nodes, d, 1), h,
                     nodes, slots, meta)
        fr[6] = c
        fr[7] = join(_q(nodes, c, 1), _q(nodes, d, 0), _q(nodes, c, 3), _q(nodes, d, 2), h,
                     nodes, slots, meta)
        fr[8] = d
        for i in range(9):
            n = fr[i]
            if n < 0:
                return np.int64(-1)
            if t1 > 0:
                v = _known(n, t1, h, nodes, meta)
                if v == -2:
                    v = _recursion(n, t1, at)
            elif h == meta[LEAF] + 1:  # quadrants of leaves: the leaf kernel, 0 generations
                v = _leaf_step(n, np.int64(0), at)
            else:
                v = _centre(n, h, nodes, slots, meta)
            if v < 0:
                return np.int64(-1)
            fr[9 + i] = v
        for i in range(4):  # the four: rows y, y+1 and columns x, x+1 of the nine's results
            r = 9 + 3 * (i >> 1) + (i & 1)
            fr[18 + i] = join(fr[r], fr[r + 1], fr[r + 3], fr[r + 4], h, nodes, slots, meta)
        for i in range(4):
            n = fr[18 + i]
            if n < 0:
                return np.int64(-1)
            v = _known(n, t2, h, nodes, meta)
            if v == -2:
                v = _recursion(n, t2, at)
            if v < 0:
                return np.int64(-1)
            fr[22 + i] = v
        out = join(fr[22], fr[23], fr[24], fr[25], h, nodes, slots, meta)
    u = np.uint64(node)
    if out >= 0 and T == np.int64(1) << (k - 2 - meta[SHIFT]):
        nodes[u, FULL] = out
    elif out >= 0:
        nodes[u, RES] = out
        nodes[u, RESJ] = T + 1
    return out


def _entry(node, T, nodes, slots, leaves, lslots, meta, R, G):
    """Centre of ``node`` after T generations; -1 if a table is full."""
    return _recursion(node, T, publish(nodes, slots, leaves, lslots, meta, R, G))


# One recursion and export per kind of leaf, each compiled only with its own leaf kernel,
# the export with one signature (the same types: value leaves pass their store's unused
# leaf table).
_SIGNATURE = f"int64(int64, int64, {TABLES}, {RULES}, {SCRATCH})"
_NO_NRT = {"_nrt": False}
step_bits = kernels.specialise(
    _entry, "step_bits", _SIGNATURE, _NO_NRT,
    _recursion=kernels.specialise(_recursion, "recursion_bits", None, _NO_NRT,
                                  _leaf_step=bitleaves.advance))
step_values = kernels.specialise(
    _entry, "step_values", _SIGNATURE, _NO_NRT,
    _recursion=kernels.specialise(_recursion, "recursion_values", None, _NO_NRT,
                                  _leaf_step=cellgrid.advance))


def advance(node: int, T: int, store, R: np.ndarray, G: np.ndarray) -> int:  # a Store
    """The centre of ``node`` after T generations (-1: a table filled up)."""
    step = step_bits if store.leaf_level else step_values
    return int(step(np.int64(node), np.int64(T), *store.tables, R, G))
