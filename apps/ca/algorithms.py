"""The engine's stepping strategies and how one is chosen (after Golly's ``lifealgo``
registry: one interface, one module per algorithm).

* ``direct``: message passing one generation at a time (thesis section 7.5; engine.py and
  kernels.py) — every rule set, advance areas, section 8.1 random outcomes and broadcasts;
* ``hashlife``: memoised quadtree jumps (apps/ca/hashlife) — deterministic rule sets on the
  whole plane, any number of generations at once; two-state rules (found by running them,
  hashlife/bits/rule.py) on a plane of 1s take its binary path of bit leaves.

Each algorithm owns the form of the state it steps (apps.ca.universe: a cell list or dense
grid for ``direct``, a tree for ``hashlife``); the engine holds whichever the last step left
and converts it when another algorithm, or an edit, needs a cell list.

``auto`` picks HashLife when it applies and the run is long enough to pay for building the
tree (:func:`choose_engine`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

from camlab88.apps.ca.rules import RuleSet

CHOICES = ("auto", "direct", "hashlife")
# "auto" uses HashLife from this many generations on (docs/perf/ca.md: below it the direct
# engine finishes first on the library's patterns, tree building included).
AUTO_MIN_GENERATIONS = 256
# ... and from this many on a dense plane (at least 1/64 of its box alive), where one direct
# generation is a few vectorised passes and the tree has little to share: a random
# 1024 x 1024 soup took 0.17 s direct / 0.56 s HashLife for 256 generations, 0.87 / 0.55 s
# for 1024 (CPU, docs/perf/ca.md).
AUTO_MIN_GENERATIONS_DENSE = 1024

Progress = Callable[[int, int], None]


class Algorithm(Protocol):
    name: str

    def unsupported(self, engine) -> str | None:  # an Engine
        """Why this algorithm cannot step ``engine`` as it is (None: it can)."""

    def advance(self, engine, generations: int,
                progress: Progress | None = None) -> None:
        """Advance ``engine`` by ``generations``, calling ``progress(done, asked)``."""


class Direct:
    """One generation at a time by message passing (Engine.step_direct)."""

    name = "direct"

    def unsupported(self, engine) -> str | None:
        return None  # every rule set (stepping without rules raises "no rules loaded")

    def advance(self, engine, generations: int,
                progress: Progress | None = None) -> None:
        engine.step_direct(generations, progress)


ALGORITHMS: dict[str, Algorithm] = {"direct": Direct()}


def get_algorithm(name: str) -> Algorithm:
    """The algorithm named; HashLife's modules (and their kernels) are imported on its
    first use, so a direct run does not pay for them."""
    if name == "hashlife" and name not in ALGORITHMS:
        from camlab88.apps.ca.hashlife.algorithm import HashLife

        ALGORITHMS[name] = HashLife()
    try:
        return ALGORITHMS[name]
    except KeyError:
        raise ValueError(f"engine must be one of {CHOICES}, not {name!r}") from None


def choose_engine(rules: RuleSet | None, generations: int, advance_area: object = None,
                  engine: str = "auto", dense: bool = False) -> str:
    """The algorithm to run ``generations`` with: ``engine`` itself if forced (a clear
    ValueError if HashLife is forced where it cannot run), else HashLife when it applies
    and the run is at least AUTO_MIN_GENERATIONS long (AUTO_MIN_GENERATIONS_DENSE on a
    ``dense`` plane)."""
    if engine not in CHOICES:
        raise ValueError(f"engine must be one of {CHOICES}, not {engine!r}")
    if engine == "direct":
        return engine
    from camlab88.apps.ca.hashlife.algorithm import reason_against

    reason = reason_against(rules, advance_area)
    if engine == "hashlife" and reason is not None:
        raise ValueError(f"HashLife cannot run here: {reason}; use the direct engine")
    if engine != "auto":
        return engine
    least = AUTO_MIN_GENERATIONS_DENSE if dense else AUTO_MIN_GENERATIONS
    return "hashlife" if reason is None and generations >= least else "direct"
