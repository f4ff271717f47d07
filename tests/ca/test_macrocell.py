"""Golly's macrocell format (.mc): reading, writing, round trips, bounded refusals."""

from __future__ import annotations

import json
import time
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca.patterns import (
    GridPattern,
    Pattern,
    PatternError,
    format_mc,
    parse_mc,
    read_pattern,
)
from camlab88.cli import main
from tests.ca.helpers import refused_pattern_file

GOLLY = Path(__file__).resolve().parents[1] / "data" / "ca" / "golly"

cells_st = st.lists(st.tuples(st.integers(0, 70), st.integers(0, 40), st.integers(1, 255)),
                    max_size=60)


def _placed(p: Pattern) -> set[tuple[int, int, int]]:
    """Cells relative to the reference point (Golly's origin)."""
    return {(int(x) - p.ref[0], int(y) - p.ref[1], int(t)) for x, y, t in zip(p.xs, p.ys, p.ts)}


@settings(max_examples=80, deadline=None)
@given(cells_st, st.tuples(st.integers(-90, 90), st.integers(-90, 90)), st.booleans())
def test_macrocell_round_trip(cells, ref, two_state: bool) -> None:
    if two_state:
        cells = [(x, y, 1) for x, y, _ in cells]
    p = Pattern.from_cells(cells, ref=ref, rule="life")
    text = format_mc(p)
    q = parse_mc(text)
    assert _placed(q) == _placed(p)
    if cells:
        assert q.rule == "B3/S23"  # Life is written as Golly's rule
    assert text.startswith("[M2]")


@settings(max_examples=60, deadline=None)
@given(cells_st, st.booleans(), st.integers(1, 40))
def test_expanding_in_small_batches_lists_the_same_cells(cells, two_state: bool, batch: int,
                                                         ) -> None:
    # the tree is expanded a batch of about BATCH cells at a time: any split gives them all
    from camlab88.apps.ca import macrocell

    if two_state:
        cells = [(x, y, 1) for x, y, _ in cells]
    p = Pattern.from_cells(cells, ref=(3, -2), rule="life")
    text = format_mc(p)
    whole = parse_mc(text)
    saved = macrocell.BATCH
    macrocell.BATCH = batch
    try:
        split = parse_mc(text)
    finally:
        macrocell.BATCH = saved
    assert _placed(split) == _placed(whole) == _placed(p) and split.ref == whole.ref


def test_a_golly_file_in_small_batches_is_the_same_pattern() -> None:
    from camlab88.apps.ca import macrocell

    whole = read_pattern(GOLLY / "primes.mc")
    saved = macrocell.BATCH
    macrocell.BATCH = 1000
    try:
        split = read_pattern(GOLLY / "primes.mc")
    finally:
        macrocell.BATCH = saved
    assert np.array_equal(split.grid, whole.grid) and split.ref == whole.ref


def test_a_leaf_line_and_a_node_line_place_cells_round_golly_origin() -> None:
    # an 8 x 8 leaf holding a glider, as the north-east quadrant of a level-4 node: the
    # root's top-left is (-8, -7), so the leaf's top-left is (0, -7)
    p = parse_mc("[M2] (golly 3.3)\n#R B3/S23\n.*$..*$***$\n4 0 1 0 0\n")
    assert _placed(p) == {(1, -7, 1), (2, -6, 1), (0, -5, 1), (1, -5, 1), (2, -5, 1)}
    multi = parse_mc("[M2]\n#R WireWorld\n1 0 3 3 1\n2 0 1 0 0\n")
    assert _placed(multi) == {(1, -1, 3), (0, 0, 3), (1, 0, 1)} and multi.rule == "WireWorld"


@pytest.mark.parametrize(("text", "where", "what"), [
    ("", "1:1", "expected '[M2]'"),
    ("[M2]\n#C only a comment\n", "2:1", "at least one node"),
    ("[M2]\n.*$..x$\n", "2:6", "found 'x'"),
    ("[M2]\n.........$\n", "2:9", "8 cells wide"),
    ("[M2]\n$$$$$$$$*$\n", "2:9", "8 tall"),
    ("[M2]\n4 0 1 0 0\n", "2:1", "node 1 is not defined"),
    ("[M2]\n.*$\n5 0 1 0 0\n", "3:1", "node 1 has level 3"),
    ("[M2]\n1 0 0 0 256\n", "2:1", "state is 0..255"),
    ("[M2]\n63 0 0 0 0\n", "2:1", "level is 1..62"),
    ("[M2]\n2 0 0 0\n", "2:1", "five numbers"),
    ("[M2]\n2 0 0 0 -1\n", "2:1", "five numbers"),
])
def test_bad_macrocell_input_names_file_line_and_column(tmp_path: Path, text: str, where: str,
                                                        what: str) -> None:
    rest = refused_pattern_file(tmp_path / "bad.mc", text)
    assert rest.startswith(f":{where}:") and what in rest


def test_a_few_lines_describing_too_many_cells_are_refused_at_once() -> None:
    # a full 8 x 8 leaf doubled up to level 30: 2**60 cells in 28 lines
    lines = ["[M2]", "********$" * 8] + [f"{lv} {lv - 3} {lv - 3} {lv - 3} {lv - 3}"
                                         for lv in range(4, 31)]
    start = time.process_time()
    with pytest.raises(PatternError, match="wider or taller than the 65536-cell plane"):
        parse_mc("\n".join(lines) + "\n")
    # one cell in every 8 x 8 square of the plane: 2**26 cells, too sparse for a grid
    sparse = ["[M2]", "*$"] + [f"{lv} {lv - 3} {lv - 3} {lv - 3} {lv - 3}"
                               for lv in range(4, 17)]
    with pytest.raises(PatternError, match="more than"):
        parse_mc("\n".join(sparse) + "\n")
    assert time.process_time() - start < 5


def test_a_dense_macrocell_pattern_becomes_a_grid() -> None:
    lines = ["[M2]", "********$" * 8] + [f"{lv} {lv - 3} {lv - 3} {lv - 3} {lv - 3}"
                                         for lv in range(4, 10)]
    p = parse_mc("\n".join(lines) + "\n")
    assert isinstance(p, GridPattern) and p.grid.shape == (512, 512) and p.grid.all()
    assert p.ref == (256, 255)


def test_golly_files_read_as_their_rle_and_round_trip() -> None:
    p = read_pattern(GOLLY / "broken-lines.mc")
    assert p.xs.size == 1766 and p.rule == ""
    assert _placed(parse_mc(format_mc(p))) == _placed(p)
    primes = read_pattern(GOLLY / "primes.mc")
    assert primes.rule == "WireWorld" and primes.xs.size == 62037
    assert set(np.unique(primes.ts).tolist()) == {1, 2, 3}


def test_ca_convert_writes_macrocell_and_ca_run_reads_it(tmp_path: Path, capsys) -> None:
    mc = tmp_path / "gun.mc"
    assert main(["ca", "convert", "gosper_gun", str(mc)]) == 0
    assert mc.read_text().startswith("[M2]")
    capsys.readouterr()
    for pattern in ("gosper_gun", str(mc)):
        assert main(["ca", "run", "--rules", "life", "--pattern", pattern, "--generations",
                     "60", "--json"]) == 0
    a, b = (json.loads(line) for line in capsys.readouterr().out.strip().splitlines()[-2:])
    assert a == b and a["population"] > 36


def test_ca_program_loads_a_macrocell_pattern() -> None:
    from camlab88.apps.ca.program.program import Options
    from tests.ca_program.driver import Driver

    d = Driver(Options(rules="wireworld", pattern=str(GOLLY / "primes.mc")))
    e = d.program.session.engine
    assert e.by_type() == {1: 3827, 2: 3911, 3: 54299}  # heads, tails, copper of the file
