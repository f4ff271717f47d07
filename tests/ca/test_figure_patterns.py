"""Figure 7.1's patterns in the library, each doing what it is known for in Life."""

from __future__ import annotations

import pytest

from camlab88.apps.ca import library
from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules


def _cells(e: Engine) -> frozenset[tuple[int, int]]:
    xs, ys, _ = e.cells()
    return frozenset(zip(xs.tolist(), ys.tolist(), strict=True))


def _period(name: str, limit: int = 40) -> tuple[int, int]:
    """(period, population) of a library pattern run in the library's Life."""
    e = Engine(load_rules(library.rules_path("life")))
    xs, ys, ts = read_pattern(library.pattern_path(name)).placed(500, 500)
    e.set_cells(xs, ys, ts)
    start = _cells(e)
    for g in range(1, limit + 1):
        e.step()
        if _cells(e) == start:
            return g, len(start)
    return 0, len(start)


@pytest.mark.claim(
    "§7.1: figure 7.1, examples of patterns from the Game of Life (the boat, the ship, the "
    "beacon, the Catherine wheel, traffic lights, the tumblers)",
    measured="each shipped pattern run in the library's Life: the boat and ship still (5 and 6 "
             "cells), beacon period 2, Catherine wheel period 4 (35 cells), traffic lights period "
             "2 (12 cells), tumbler period 14",
    verdict="agrees (the figure's pictures are not in our copy of the thesis: the patterns are "
            "the standard ones of those names)")
@pytest.mark.parametrize(("name", "period", "population"), [
    ("boat", 1, 5), ("ship", 1, 6), ("beacon", 2, 8), ("catherine_wheel", 4, 35),
    ("traffic_lights", 2, 12), ("tumbler", 14, 16),
])
def test_figure_7_1_patterns_oscillate_as_named(name: str, period: int, population: int) -> None:
    assert _period(name) == (period, population)
