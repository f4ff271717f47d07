"""The shipped library works: Life demos, over-grazing, the maze solved, the primes machine."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.apps.ca import library, maze, turing
from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.library_build import generated
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules, parse_rules


def test_generated_library_files_are_up_to_date() -> None:
    for name, text in generated().items():
        assert (library.LIBRARY / name).read_text() == text, name


def test_every_library_file_loads() -> None:
    found = library.names()
    assert {"life", "maze", "overgrazing", "turing_primes"} <= set(found["rules"])
    for name in found["rules"]:
        load_rules(library.rules_path(name))
    for name in found["patterns"]:
        assert len(read_pattern(library.pattern_path(Path(name).stem)).cell_set()) > 0
    with pytest.raises(FileNotFoundError, match="library"):
        library.rules_path("no_such_rules")


def _place(rules: str, pattern: str, x: int = 1000, y: int = 1000) -> Engine:
    e = Engine(load_rules(library.rules_path(rules)))
    xs, ys, ts = read_pattern(library.pattern_path(pattern)).placed(x, y)
    e.set_cells(xs, ys, ts)
    return e


def test_overgrazing_block_ages_grazes_and_regenerates() -> None:
    e = _place("overgrazing", "grazing_soup")
    e.step(50)
    assert e.population > 0
    e = Engine(load_rules(library.rules_path("overgrazing")))
    e.set_cells([10, 11, 10, 11], [10, 10, 11, 11], 1)  # a block: still life in Life
    seen = []
    for _ in range(8):
        seen.append(sorted(e.by_type().items()))
        e.step()
    assert seen == [[(1, 4)], [(2, 4)], [(3, 4)], [(4, 4)], [(5, 4)], [(6, 4)], [(7, 4)], []]
    # No birth on grazed ground: three living cells next to a grazed cell.
    e.set_cells([20, 21, 22, 21], [20, 20, 20, 21], [1, 1, 1, 5])
    e.step()
    assert e.get(21, 21) == 6 and e.get(21, 19) == 1


def test_maze_runner_solves_the_demo_maze_by_the_shortest_path() -> None:
    pattern, exit_cell, shortest = maze.build()
    e = _place("maze", "maze_demo", 0, 0)
    ex, ey = exit_cell
    arrival = None
    walls = e.by_type()[1]
    for _ in range(shortest + 3):
        if e.get(ex, ey) == 2 and arrival is None:
            arrival = e.generation
        e.step()
    assert arrival == shortest
    assert e.by_type()[1] == walls  # walls are static


def _maze(text: list[str]) -> Engine:
    e = Engine(load_rules(library.rules_path("maze")))
    for y, row in enumerate(text):
        for x, ch in enumerate(row):
            if ch in "#Ht":
                e.set(x, y, {"#": 1, "H": 2, "t": 3}[ch])
    return e


def _runners(e: Engine) -> list[tuple[int, int, int]]:
    return sorted((int(x), int(y), int(t)) for x, y, t in zip(e.xs, e.ys, e.ts) if t > 1)


@pytest.mark.claim("§7.4.1: where more than one cell will do the runner splits and continues "
                   "in both directions; runners which meet annihilate each other",
                   measured="a runner at a T junction becomes two heads the next generation; "
                   "two runners meeting head on in a corridor (an odd and an even gap "
                   "between them) leave no head or tail two generations after they meet",
                   verdict="agrees")
def test_maze_runners_split_and_meeting_runners_annihilate() -> None:
    e = _maze(["#######", "#tH...#", "###.###", "  #.#", "  ###"])
    e.step(2)
    assert [c for c in _runners(e) if c[2] == 2] == [(3, 2, 2), (4, 1, 2)]  # split in two
    for row in ("#tH......Ht#", "#tH.......Ht#"):
        e = _maze(["#" * len(row), row, "#" * len(row)])
        walls = e.by_type()[1]
        met = None
        for _ in range(12):
            heads = [x for x, _, t in _runners(e) if t == 2]
            if met is None and len(heads) == 2 and heads[1] - heads[0] <= 2:
                met = e.generation
            e.step()
        assert met is not None and _runners(e) == [] and e.by_type()[1] == walls


def test_maze_runner_dies_in_a_dead_end() -> None:
    text = ["#####", "#...#", "#####"]
    e = Engine(load_rules(library.rules_path("maze")))
    for y, row in enumerate(text):
        for x, ch in enumerate(row):
            if ch == "#":
                e.set(x, y, 1)
    e.set(1, 1, 3)
    e.set(2, 1, 2)
    e.step(5)
    assert set(e.by_type()) == {1}


def _verdict(n: int, limit: int = 20000) -> tuple[str, int]:
    rules = parse_rules(turing.rules_text())
    forms = {t: v for v, t in turing.verdict_forms().items()}
    cross = turing.cross_forms()
    e = Engine(rules)
    xs, ys, ts = turing.pattern(n).placed(500, 500)
    e.set_cells(xs, ys, ts)
    while e.generation < limit:
        e.step(25)
        found = [forms[t] for t in e.by_type() if t in forms]
        if found:
            return found[0], e.generation
        heads = [t for t in e.by_type() if t >= turing.FIRST_HEAD and t not in cross]
        assert len(heads) == 1 and e.by_type()[heads[0]] == 1
    raise AssertionError(f"no verdict for {n}")


def _is_prime(n: int) -> bool:
    return n > 1 and all(n % d for d in range(2, int(n ** 0.5) + 1))


@pytest.mark.parametrize("n", [2, 3, 4, 6, 7, 9, 15, 21, 23, 25, 29, 31, 49, 53])
def test_turing_machine_verdicts(n: int) -> None:
    assert _verdict(n)[0] == ("YES" if _is_prime(n) else "NO")


def test_failure_cross_is_hidden_until_the_head_runs_into_it() -> None:
    hidden, shown = turing.cross_forms()
    e = Engine(parse_rules(turing.rules_text()))
    xs, ys, ts = turing.pattern(9).placed(500, 500)
    e.set_cells(xs, ys, ts)
    assert e.by_type()[hidden] == 9 and shown not in e.by_type()
    while shown not in e.by_type():
        assert e.by_type()[hidden] == 9  # hidden while the machine works
        e.step()
    assert e.generation > 30
    e.step(4)
    assert e.by_type()[shown] == 9 and hidden not in e.by_type()


@pytest.mark.claim("§7.4.2: the failing head runs into \"an area of invisible cells in the "
                   "form of a cross, which then became visible\"", measured="the cross's nine "
                   "cells drawn in the dead colour (colour and monochrome pages, headless "
                   "render) until the machine finds 9 not prime, then red",
                   verdict="agrees")
def test_failure_cross_is_drawn_dead_until_shown() -> None:
    from camlab88.apps.ca import render
    from camlab88.apps.ca.engine import Rect
    from camlab88.apps.ca.program import colours

    rules = parse_rules(turing.rules_text())
    hidden, shown = turing.cross_forms()
    for kind in ("colour", "mono"):
        page = colours.page(kind, rules, grid=True)
        assert page[1 + hidden] == page[1], kind  # index 1 is a dead cell
        assert page[1 + shown] != page[1], kind
    e = Engine(rules)
    xs, ys, ts = turing.pattern(9).placed(500, 500)
    e.set_cells(xs, ys, ts)
    cross = Rect(492, 501, 496, 505)  # the cross, left of the machine on the head's row
    for mono in (False, True):
        assert not render.render(e, cross, zoom=4, monochrome=mono).any()
    while shown not in e.by_type():
        e.step()
    e.step(4)
    for mono in (False, True):
        img = render.render(e, cross, zoom=4, monochrome=mono)
        assert img.reshape(-1, 3).any(axis=1).sum() == 9 * 9  # nine cells of 3 x 3 pixels


def test_turing_demo_patterns_25_and_23() -> None:
    forms = {t: v for v, t in turing.verdict_forms().items()}
    for name, want in (("primes_25", "NO"), ("primes_23", "YES")):
        e = _place("turing_primes", name)
        e.step(1500)
        assert [forms[t] for t in e.by_type() if t in forms] == [want]
        # The number on the top row is intact afterwards.
        top = sorted(int(x) - 1000 for x, y, t in zip(e.xs, e.ys, e.ts) if y == 1000 and t == 1)
        n = int(name.split("_")[1])
        assert top == [i + 1 for i, b in enumerate(bin(n)[2:]) if b == "1"]
