"""Golly's own patterns run by both programs: bgolly (the oracle) and our engines, direct and
HashLife, must leave the same cells in the same places (relative to Golly's origin, which
our readers make the reference point) at several generations."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.apps.ca import library
from camlab88.apps.ca.engine import CENTRE, Engine
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules
from tests.ca.golly_oracle import DATA, golly_cells, need_bgolly

CASES = [  # file in tests/data/ca/golly, our rule set, generations, a Golly rule table?
    ("blom.rle", "life", (0, 100, 1500), False),  # Life/Methuselahs
    ("iwona.rle", "life", (300, 2000), False),  # Life/Methuselahs
    ("period-52-glider-gun.rle", "life", (52, 500), False),  # Life/Guns
    ("gun-p165mwss.rle", "life", (165, 700), False),  # Life/Guns
    ("p138.rle", "life", (69, 138), False),  # Life/Oscillators
    ("line-puffer-unstable.rle", "life", (400,), False),  # Life/Puffers
    ("broken-lines.mc", "life", (0, 1000), False),  # HashLife (a macrocell file)
    ("primes.mc", "wireworld", (0, 1, 120), True),  # WireWorld
    ("Langtons-Loops.rle", "langtons_loops", (0, 1, 151, 400), True),  # Loops
    ("acorn.lif", "life", (0, 1, 500), False),  # Life/Methuselahs, Life 1.05 ('#P' alone)
    ("rabbits.lif", "life", (0, 300), False),  # Life/Methuselahs, Life 1.05
    ("breeder.lif", "life", (0, 120), False),  # Life/Breeders, Life 1.05, 258 '#P' blocks
    ("acorn_106.life", "life", (0, 500), False),  # acorn written as Life 1.06 (SOURCES.md)
]


def _ours(path: Path, rules: str, generations: int, algorithm: str
          ) -> set[tuple[int, int, int]]:
    p = read_pattern(path)
    e = Engine(load_rules(library.rules_path(rules)), algorithm=algorithm)
    e.set_cells(*p.placed(CENTRE, CENTRE))
    e.step(generations)
    xs, ys, ts = e.cells()
    return {(int(x) - CENTRE, int(y) - CENTRE, int(t)) for x, y, t in zip(xs, ys, ts)}


@pytest.mark.parametrize(("name", "rules", "generations", "table"), CASES,
                         ids=[c[0] for c in CASES])
def test_golly_and_our_engines_leave_the_same_cells(name: str, rules: str,
                                                    generations: tuple[int, ...],
                                                    table: bool, tmp_path: Path) -> None:
    need_bgolly()
    for g in generations:
        theirs = golly_cells(DATA / name, g, tmp_path / f"{g}.mc", table)
        assert theirs, f"bgolly left no cells of {name} at generation {g}"
        for algorithm in ("direct", "hashlife"):
            assert _ours(DATA / name, rules, g, algorithm) == theirs, (name, g, algorithm)


@pytest.mark.parametrize("name", ["broken-lines.mc", "primes.mc", "blom.rle"])
def test_golly_reads_the_macrocell_files_we_write(name: str, tmp_path: Path) -> None:
    """`ca convert` to .mc, then bgolly loads our file: the cells it writes back (generation
    0) are the pattern's, in the same places."""
    from camlab88.cli import main

    ours = tmp_path / "ours.mc"
    assert main(["ca", "convert", str(DATA / name), str(ours)]) == 0
    p = read_pattern(DATA / name)
    expected = {(int(x) - p.ref[0], int(y) - p.ref[1], int(t))
                for x, y, t in zip(p.xs, p.ys, p.ts)}
    assert golly_cells(ours, 0, tmp_path / "back.mc", name == "primes.mc") == expected


def test_our_macrocell_nodes_are_the_ones_golly_writes(tmp_path: Path) -> None:
    """bgolly writes broken-lines.mc back out; our writer gives the same node lines."""
    from camlab88.apps.ca.patterns import format_mc

    golly_cells(DATA / "broken-lines.mc", 0, tmp_path / "golly.mc", False)
    theirs = [s for s in (tmp_path / "golly.mc").read_text().splitlines()
              if not s.startswith(("[", "#"))]
    ours = [s for s in format_mc(read_pattern(DATA / "broken-lines.mc")).splitlines()
            if not s.startswith(("[", "#"))]
    assert ours == theirs


def test_golly_reads_persian_rugs_lif_as_we_do(tmp_path: Path) -> None:
    """Life-Like/persian-rugs.lif ('#R B234', a rule we hold no rule set for): the cells
    bgolly loads (generation 0) are the ones we read, and we keep its rule."""
    p = read_pattern(DATA / "persian-rugs.lif")
    assert p.rule == "B234"
    ours = {(int(x) - p.ref[0], int(y) - p.ref[1], int(t)) for x, y, t in zip(p.xs, p.ys, p.ts)}
    assert golly_cells(DATA / "persian-rugs.lif", 0, tmp_path / "rugs.mc", False) == ours
