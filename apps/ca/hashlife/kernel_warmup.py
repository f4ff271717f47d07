"""Every HashLife kernel called once, with the argument types real runs use.

The completion of the "HashLife" and "binary HashLife" kernel groups
(protocols.kernel_notice): after the first cold compile of either, both compile, so Life
(the binary path, which also uses the generic tree's conversions) and a later rule set of
more life-forms (the generic path: the Turing machine, the maze, the circuits) share one
compile. Short runs through the engine itself, on both edge modes, with a node-table limit
small enough to make the garbage collector run.
"""

from __future__ import annotations

from apps.ca.engine import CENTRE, Engine
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
