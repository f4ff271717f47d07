"""HashLife (Gosper 1984) for any deterministic rule set of the thesis's rule language.

The plane is a quadtree of hash-consed nodes whose leaves are life-form values; each node of
level k remembers its centre after 2**j generations (j <= k - 2 - s, where 2**s is at least
the rules' message reach), so repeated regions of space and time are computed once.  See
docs/ca.md ("Jumping ahead: HashLife") and docs/perf/ca.md.

One tree (``tree``: the universe an engine adopts, the jumps and their memory handling,
``plane``: the 65536-square plane's wrapping and bounded edges, ``algorithm``: the strategy
the engine calls) over one node store (``store``, with ``upkeep``: growth and garbage
collection), one memoised recursion (``evolve``), one conversion each way (``grid``: leaves
to a tree, ``bits.window``: a dense window to bit leaves; ``cells``: cell lists to a tree,
``listing``: a tree's cells listed) and one census (``census``); the kind of leaf is chosen
per run, and only the leaf kernel depends on it:

* ``generic`` — leaves are single cells holding life-form values (any deterministic rules);
  the base case runs the rules on a small grid (``cellgrid``, with ``leaf``: one
  generation of the rules);
* ``bits.run`` — two-state rules on a plane of 1s: 16 x 16-cell leaves of bits advanced by
  bit operations (``bits.leaves``), the same answers with far fewer, cheaper nodes.
"""

from camlab88.base.kernel_notice import announce_compiles

_WARM = "camlab88.apps.ca.hashlife.kernel_warmup:compile_"  # + the group's part
# Cold compile times (CPU) measured on the project's 2-core machine (docs/perf/startup.md).
# Each group completes alone, so a run compiles only the groups it touches: what every jump
# needs (the store, the census, the levels of a tree, compiled into the conversions), each
# kind of leaf with the recursion compiled for it (``evolve`` is in no group: its kernels
# compile only inside a kind's entry, announced by that kind's leaf kernel), the cell lists
# in, the cells listed out, the tables' growth and collection.  The rule interpreter is its
# own group (every run runs it: the binary one to build its table).  So Life's first run
# compiles neither the value leaves nor the cell lists, and a multi-state run's first
# compile not the bit leaves.
announce_compiles("HashLife rule", 1.0, f"{__name__}.leaf")
announce_compiles("HashLife", 3.0, *(f"{__name__}.{m}" for m in ("store", "census", "grid")),
                  completion=_WARM + "common")
announce_compiles("HashLife bit-leaf", 4.0, f"{__name__}.bits.leaves", f"{__name__}.bits.window",
                  completion=_WARM + "bits")
announce_compiles("HashLife value-leaf", 4.0, f"{__name__}.cellgrid", completion=_WARM + "values")
announce_compiles("HashLife cell-list", 2.0, f"{__name__}.cells", completion=_WARM + "cells")
announce_compiles("HashLife cell listing", 1.0, f"{__name__}.listing",
                  completion=_WARM + "listing")
announce_compiles("HashLife growth and collection", 2.0, f"{__name__}.upkeep",
                  completion=_WARM + "upkeep")
