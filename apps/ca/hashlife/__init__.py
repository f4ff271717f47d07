"""HashLife (Gosper 1984) for any deterministic rule set of the thesis's rule language.

The plane is a quadtree of hash-consed nodes whose leaves are life-form values; each node of
level k remembers its centre after 2**j generations (j <= k - 2 - s, where 2**s is at least
the rules' message reach), so repeated regions of space and time are computed once.  See
docs/ca.md ("Jumping ahead: HashLife") and docs/perf/ca.md.

One tree (``tree``: the universe an engine adopts, the jumps and their memory handling,
``plane``: the 65536-square plane's wrapping and bounded edges, ``algorithm``: the strategy
the engine calls) over a leaf strategy chosen per run:

* ``generic`` — leaves of life-form values: ``store`` (the node table and its garbage
  collection), ``leaf`` (one generation of the rules on a small grid), ``evolve`` (the
  memoised recursion), ``convert`` and ``census`` (cells and statistics);
* ``bits.run`` — two-state rules on a plane of 1s: 16 x 16-cell leaves of bits advanced by
  bit operations, the same answers with far fewer, cheaper nodes (``bits`` holds its
  table, base case, recursion, conversions and census).
"""

from base.kernel_notice import announce_compiles

_WARM = "apps.ca.hashlife.kernel_warmup:compile_"  # + the group's part
# Cold compile times (CPU) measured on the project's 2-core machine (docs/perf/startup.md).
# Each group completes alone, so a run compiles only the groups it touches; the rule
# interpreter is its own group (both paths run it: the binary one to build its table).
announce_compiles("HashLife rule", 1.0, f"{__name__}.leaf")
announce_compiles("HashLife", 6.0, *(f"{__name__}.{m}" for m in (
    "store", "evolve", "convert", "census")), completion=_WARM + "generic")
announce_compiles("binary HashLife", 7.0, *(f"{__name__}.bits.{m}" for m in (
    "rule", "store", "leaves", "evolve", "convert", "census", "run")),
    completion=_WARM + "binary")
announce_compiles("binary HashLife cell-list", 2.0, f"{__name__}.bits.cells",
                  completion=_WARM + "bit_cells")
announce_compiles("binary HashLife growth and collection", 2.0, f"{__name__}.bits.collect",
                  completion=_WARM + "bit_upkeep")
