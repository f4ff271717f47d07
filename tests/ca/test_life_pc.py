"""Life 1.05 / 1.06 (.lif, .life) read as Golly's readpclife reads them; bad files named.

Golly's own .lif files are checked against bgolly in test_golly_agreement.py; here the
corners of the format: blocks, '#P' without numbers, 1.06 cells, errors, the CLI."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca.patterns import PatternError, parse_life, read_pattern, write_pattern
from tests.ca.helpers import refused_pattern_file


def _cells(text: str) -> set[tuple[int, int]]:
    p = parse_life(text)
    return {(int(x) - p.ref[0], int(y) - p.ref[1]) for x, y in zip(p.xs, p.ys)}


def test_blocks_rows_and_origin() -> None:
    text = "#Life 1.05\n#D two blocks\n#N\n#P -2 -1\n*.*\n.*\n#P 10 20\n**\n"
    assert _cells(text) == {(-2, -1), (0, -1), (-1, 0), (10, 20), (11, 20)}
    p = parse_life(text)
    assert p.rule == "B3/S23" and p.comments == ["two blocks"]


def test_hash_p_without_numbers_keeps_the_position() -> None:
    # as sscanf leaves x, y alone: the second block continues below the first
    assert _cells("#Life 1.05\n#P\n*\n#P\n.*\n") == {(0, 0), (1, 1)}
    assert _cells("#Life 1.05\n#P 5\n*\n") == {(5, 0)}


def test_rule_line_and_life_106_cells() -> None:
    p = parse_life("#Life 1.06\n#R 23/36\n0 0\n-1 3\n  \n2 -4\n")
    assert p.rule == "23/36"
    assert _cells("#Life 1.06\n0 0\n-1 3\n2 -4\n") == {(0, 0), (-1, 3), (2, -4)}


@pytest.mark.parametrize(("text", "where", "words"), [
    ("x = 3, y = 1\n3o!\n", ":1:1:", "'#Life 1.05' or '#Life 1.06'"),
    ("#Life 1.06\n0 0\n7 x\n", ":3:1:", "two integers"),
    ("#Life 1.06\n0 0\n2000000000 0\n", ":3:1:", "beyond any plane"),
    ("#Life 1.06\n0 0\n" + "9" * 40 + " 0\n", ":3:1:", "two integers"),
    ("#Life 1.06\n0 0\n70000 0\n", "wider or taller", "65536"),
])
def test_bad_files_name_the_file_and_line(tmp_path: Path, text: str, where: str,
                                          words: str) -> None:
    rest = refused_pattern_file(tmp_path / "bad.lif", text)
    assert where in rest and words in rest


def test_written_only_in_other_formats(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="read, not written"):
        write_pattern(tmp_path / "out.lif", parse_life("#Life 1.06\n0 0\n"))
    assert not (tmp_path / "out.lif").exists()


def test_ca_convert_reads_a_lif(tmp_path: Path) -> None:
    from camlab88.cli import main

    data = Path(__file__).resolve().parents[1] / "data" / "ca" / "golly"
    out = tmp_path / "acorn.rle"
    assert main(["ca", "convert", str(data / "acorn.lif"), str(out)]) == 0
    assert read_pattern(out).cell_set() == read_pattern(data / "acorn.lif").cell_set()


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet="#LifeP.*NR0123456789- \n\r\tD", max_size=300))
def test_any_text_reads_or_fails_with_a_located_error(body: str) -> None:
    try:
        p = parse_life("#Life 1.05\n" + body)
    except PatternError as exc:
        assert str(exc).startswith("<lif>:")
    else:
        assert p.width <= 65536 and p.height <= 65536
