"""Pattern interchange: native, RLE (Golly/LifeWiki style) and .cells, both directions."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca.library import pattern_path
from camlab88.apps.ca.patterns import (
    ORIENTATIONS,
    Pattern,
    PatternError,
    format_cells,
    format_native,
    format_rle,
    golly_rule,
    parse_cells,
    parse_native,
    parse_rle,
    read_pattern,
    write_pattern,
)

DATA = Path(__file__).resolve().parents[1] / "data" / "ca"

cells_st = st.lists(st.tuples(st.integers(0, 40), st.integers(0, 30), st.integers(1, 255)),
                    max_size=60)


def _pattern(cells, ref=(0, 0)) -> Pattern:
    return Pattern.from_cells(cells, ref=ref, name="p", rule="life")


@settings(max_examples=60, deadline=None)
@given(cells_st, st.tuples(st.integers(-5, 50), st.integers(-5, 50)))
def test_native_round_trip(cells, ref) -> None:
    p = _pattern(cells, ref)
    q = parse_native(format_native(p))
    assert q.cell_set() == p.cell_set() and q.ref == p.ref and q.name == "p"


@settings(max_examples=60, deadline=None)
@given(cells_st, st.tuples(st.integers(-5, 50), st.integers(-5, 50)))
def test_rle_round_trip_multistate(cells, ref) -> None:
    p = _pattern(cells, ref)
    text = format_rle(p)
    assert all(len(line) <= 70 for line in text.splitlines() if not line.startswith("#"))
    q = parse_rle(text)
    assert q.cell_set() == p.cell_set()
    if cells:
        assert q.ref == p.ref and q.rule == "B3/S23"  # Life is written as Golly's rule


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 30), st.integers(0, 20)), max_size=50))
def test_cells_round_trip(points) -> None:
    p = _pattern([(x, y, 1) for x, y in points])
    assert parse_cells(format_cells(p)).cell_set() == p.cell_set()


def test_lifewiki_style_rle_reads_the_gosper_gun() -> None:
    p = read_pattern(DATA / "lifewiki_style.rle")
    q = read_pattern(pattern_path("gosper_gun"))
    assert p.cell_set() == q.cell_set() and len(p.cell_set()) == 36
    assert p.name == "Gosper glider gun" and p.rule == "B3/S23"
    assert (p.width, p.height) == (36, 9)
    assert len(p.comments) == 3
    assert p.author == "Bill Gosper"  # the '#O' line is kept ...
    out = format_rle(p)
    assert "#O Bill Gosper" in out.splitlines()  # ... and written back
    assert parse_rle(out).author == "Bill Gosper"
    assert parse_native(format_native(p)).author == "Bill Gosper"


@pytest.mark.parametrize(("rule", "header", "comment"), [
    ("life", "x = 3, y = 1, rule = B3/S23", None),
    ("B36/S23", "x = 3, y = 1, rule = B36/S23", None),
    ("23/3", "x = 3, y = 1, rule = 23/3", None),
    ("overgrazing", "x = 3, y = 1", "#C camlab88 rules: overgrazing"),
    ("turing_primes", "x = 3, y = 1", "#C camlab88 rules: turing_primes"),
])
def test_rle_rule_field_only_for_golly_rules(rule: str, header: str, comment: str | None,
                                             ) -> None:
    """Golly rejects unknown rule names in the header: a library rule set's name goes in a
    comment line (read back as the pattern's rule)."""
    p = Pattern.from_cells([(0, 0, 1), (2, 0, 1)], rule=rule)
    lines = format_rle(p).splitlines()
    assert header in lines
    if comment is not None:
        assert comment in lines and not any("rule =" in line for line in lines)
        assert parse_rle("\n".join(lines)).rule == rule
    assert golly_rule(rule) == (None if comment else header.split("rule = ")[1])


def test_rle_details() -> None:
    p = parse_rle("#C two states\n  x=5,y=3, rule = b3/s23\n2o$3$bo\n2b3o!  trailing text")
    # A line break does not end a row: '2b3o' continues row 3 after 'bo'.
    assert p.cell_set() == {(0, 0, 1), (1, 0, 1), (1, 4, 1), (4, 4, 1), (5, 4, 1),
                            (6, 4, 1)}
    multi = parse_rle("x = 5, y = 1, rule = Custom\n.A2pBpX!")  # leading dead cell dropped
    assert multi.cell_set() == {(0, 0, 1), (1, 0, 26), (2, 0, 26), (3, 0, 48)}
    assert format_rle(multi).splitlines()[-1] == "A2pBpX!"
    pos = parse_rle("#CXRLE Pos=-2,-1 Gen=0\nx = 1, y = 1\no!")
    assert pos.ref == (2, 1)


READERS = {"rle": (parse_rle, "bad.rle"), "native": (parse_native, "bad.pat")}


@pytest.mark.parametrize(("reader", "text", "line", "words"), [
    ("rle", "", 1, "RLE header"),
    ("rle", "#N x\nfoo\n", 2, "RLE header"),
    ("rle", "x = 2, y = 1\n2o", 2, "'!'"),
    ("rle", "x = 2, y = 1\n2z!", 2, "expected b, o"),
    ("rle", "x = 2, y = 1\n02o!", 2, "leading zero"),
    ("rle", "x = 2, y = 1\npZ!", 2, "expected A..X"),
    ("rle", "x = 2, y = 1\n2 o!", 2, "cell symbol after the repeat count"),
    ("rle", "x = 2, y = 1\nyX!", 2, "above 255"),
    ("rle", "x = 2, y = 1\n999999999o!", 2, "wider or taller than the 65536-cell plane"),
    ("rle", "x = 2, y = 1\n70000$o!", 2, "wider or taller"),
    ("native", "", 1, "CAMLAB88-CA-PATTERN 1"),
    ("native", "CAMLAB88-CA-PATTERN 1\nbogus 1\n", 2, "expected name"),
    ("native", "CAMLAB88-CA-PATTERN 1\nref 1\ncells 0\nend\n", 2, "'ref x y'"),
    ("native", "CAMLAB88-CA-PATTERN 1\n", 1, "'cells n'"),
    ("native", "CAMLAB88-CA-PATTERN 1\ncells 2\n0 0 1\n", 3, "file ended early"),
    ("native", "CAMLAB88-CA-PATTERN 1\ncells 1\n0 0\nend\n", 3, "'x y life-form'"),
    ("native", "CAMLAB88-CA-PATTERN 1\ncells 1\n0 0 0\nend\n", 3, "1..65535"),
    ("native", "CAMLAB88-CA-PATTERN 1\ncells 1\n0 0 1\n", 4, "'end'"),
], ids=lambda v: v if isinstance(v, str) else f"line{v}")
def test_errors_name_the_file_and_line(reader: str, text: str, line: int, words: str) -> None:
    parse, name = READERS[reader]
    with pytest.raises(PatternError) as info:
        parse(text, name)
    assert info.value.line == line and words in str(info.value)
    assert str(info.value).startswith(f"{name}:{line}:")


def test_cells_errors_and_limits() -> None:
    with pytest.raises(PatternError, match=r"bad.cells:2:3: expected '.' or 'O'"):
        parse_cells("!c\n.Ox\n", "bad.cells")
    with pytest.raises(ValueError, match="one life-form"):
        format_cells(_pattern([(0, 0, 2)]))
    with pytest.raises(ValueError, match="up to 255"):
        format_rle(_pattern([(0, 0, 300)]))
    big = parse_native(format_native(_pattern([(0, 0, 300)])))
    assert big.cell_set() == {(0, 0, 300)}


def test_eight_orientations_distinct_and_consistent() -> None:
    r = _pattern([(0, 0, 1), (1, 0, 1), (2, 0, 1), (0, 1, 1), (1, 2, 1)], ref=(1, 1))
    shapes = set()
    for name in ORIENTATIONS:
        xs, ys, _ = r.placed(100, 100, name)
        shapes.add(frozenset(zip(xs.tolist(), ys.tolist())))
    assert len(shapes) == 8
    # Four clockwise quarter turns are the identity; reference point stays put.
    p = r
    for _ in range(4):
        xs, ys, ts = p.placed(1000, 1000, "rot90")
        p = Pattern.from_cells(list(zip(xs.tolist(), ys.tolist(), ts.tolist())),
                               ref=(1000, 1000))
    assert p.cell_set() == r.cell_set() and p.ref == r.ref
    xs, ys, _ = r.placed(100, 100, "rot180")
    assert (101, 101) in set(zip(xs.tolist(), ys.tolist()))  # (0,0) rel (1,1) -> (+1,+1)
    with pytest.raises(ValueError, match="unknown orientation"):
        r.placed(0, 0, "sideways")


def test_files_written_atomically_in_each_format(tmp_path: Path) -> None:
    p = read_pattern(pattern_path("gosper_gun"))
    for ext in (".pat", ".rle", ".cells"):
        out = tmp_path / f"gun{ext}"
        write_pattern(out, p)
        assert read_pattern(out).cell_set() == p.cell_set()
    assert sorted(f.name for f in tmp_path.iterdir()) == ["gun.cells", "gun.pat", "gun.rle"]
    assert np.array_equal(read_pattern(tmp_path / "gun.pat").ts, p.ts)
