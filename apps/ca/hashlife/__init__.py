"""HashLife (Gosper 1984) for any deterministic rule set of the thesis's rule language.

The plane is a quadtree of hash-consed nodes whose leaves are life-form values; each node of
level k remembers its centre after 2**j generations (j <= k - 2 - s, where 2**s is at least
the rules' message reach), so repeated regions of space and time are computed once.  See
docs/ca.md ("Jumping ahead: HashLife") and docs/perf/ca.md.

One tree (``tree``: the universe an engine adopts, the jumps and their memory handling,
``plane``: the 65536-square plane's wrapping and bounded edges, ``algorithm``: the strategy
the engine calls) over one node store (``store``: its growth and garbage collection too),
one memoised recursion (``evolve``), one conversion each way (``bits.window``: a dense
window to bit leaves; ``cells``: cell lists to a tree, ``listing``: a tree's cells listed)
and one census (``census``); the kind of leaf is chosen per run, and only the leaf kernel
depends on it:

* ``generic`` — leaves are single cells holding life-form values (any deterministic rules);
  the base case runs the rules on a small grid (``leaf``: one generation of the rules);
* ``bits.run`` — two-state rules on a plane of 1s: 16 x 16-cell leaves of bits advanced by
  bit operations, the same answers with far fewer, cheaper nodes.

Every compiled kernel of these is in ``kernels`` (one file: numba's cache checks a kernel
against its own file only, and they call each other).
"""

from camlab88.base.kernel_notice import announce_compiles

_K = f"{__name__}.kernels:"  # + a kernel's name
_WARM = "camlab88.apps.ca.hashlife.kernel_warmup:compile_"  # + the group's part
# The kernel groups of the compile notice (every kernel is in ``kernels``), the kernels
# Python calls named; the kernels they call compile inside them.  Cold compile times (CPU)
# measured on the project's 2-core machine (docs/perf/startup.md).  Each group completes
# alone, so a run compiles only the groups it touches: what every jump needs (the store, the
# census, the levels of a tree, compiled into the conversions), each kind of leaf with the
# recursion compiled for it (the recursion is in no group: it compiles only inside a kind's
# entry, announced by that kind's leaf kernel), the cell lists in, the cells listed out, the
# tables' growth and collection.  The rule interpreter is its own group (every run runs it:
# the binary one to build its table).  So Life's first run compiles neither the value
# leaves nor the cell lists, and a multi-state run's first compile not the bit leaves.
GROUPS: dict[str, tuple[float, tuple[str, ...], str | None]] = {
    "HashLife rule": (1.0, ("generation", "_interpret"), None),
    "HashLife": (3.0, ("join", "towers", "count", "occupy", "_mask", "_leaf_mask", "levels"),
                 "common"),
    "HashLife bit-leaf": (4.0, ("advance_bits", "grid_leaves", "build"), "bits"),
    "HashLife value-leaf": (4.0, ("advance_values",), "values"),
    "HashLife cell-list": (2.0, ("morton", "from_cells", "any_live"), "cells"),
    "HashLife cell listing": (1.0, ("listing", "_emit"), "listing"),
    "HashLife growth and collection": (2.0, ("rehash", "collect"), "upkeep"),
}
for _label, (_seconds, _names, _part) in GROUPS.items():
    announce_compiles(_label, _seconds, *(_K + n for n in _names),
                      completion=_WARM + _part if _part else None)
