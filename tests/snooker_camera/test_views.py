"""The view file: round trip, and errors at file:line:col."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.snooker.camera.views import (
    View,
    ViewFileError,
    parse_views,
    read_views,
    views_text,
    write_views,
)
from tests.support.refusals import refusal_of


def test_round_trip_is_bit_identical(tmp_path: Path) -> None:
    views = [View(1, (0.1 + 0.2, -4.5, 1.2), (0.0, 0.0, 0.0), 50.0),
             View(2, (1e-17, 2.0, 3.0), (1 / 3, 0.0, 0.0), 135.0)]
    p = tmp_path / "v.views"
    write_views(p, views, comments=["made by\na test"])
    text = p.read_text()
    assert text.startswith("# made by a test\n")
    assert read_views(p) == views


@pytest.mark.parametrize(("text", "where", "what"), [
    ("1 0 0 0 1 1 1\n", "1:14", "expected 8 fields"),
    ("# c\n1 0 0 0 1 1 1 50\n3 0 0 0 1 1 1 50\n", "3:1", "frame 3 where frame 2"),
    ("1 0 0 x 1 1 1 50\n", "1:7", "oz 'x' is not a finite number"),
    ("1 0 0 0 1 1 1 5\n", "1:15", "focal length 5 mm is outside 8 to 2000"),
    ("1 0 0 0 0 0 0 50\n", "1:3", "the same point"),
    ("0 0 0 0 1 1 1 50\n", "1:1", "not an integer >= 1"),
    ("1 0 0 nan 1 1 1 50\n", "1:7", "not a finite number"),
    ("1 0 0 1_0 1 1 1 50\n", "1:7", "oz '1_0' is not a finite number"),
    ("1 0 0 1e999 1 1 1 50\n", "1:7", "not a finite number"),
    ("# only\n", "2:1", "no frames"),
])
def test_errors_name_line_and_column(text: str, where: str, what: str) -> None:
    with pytest.raises(ViewFileError) as err:
        parse_views(text, "f.views")
    assert str(err.value).startswith(f"f.views:{where}: ") and what in str(err.value)


def test_non_ascii_byte_position(tmp_path: Path) -> None:
    p = tmp_path / "v"
    p.write_bytes(b"1 0 0 0 1 1 1 50\n2 0 \xb2 0 1 1 1 50\n")
    with pytest.raises(ViewFileError, match=r"v:2:5: non-ASCII"):
        read_views(p)


finite = st.floats(allow_nan=False, allow_infinity=False, min_value=-1e6, max_value=1e6)
vec = st.tuples(finite, finite, finite)


@settings(max_examples=200, deadline=None)
@given(st.integers(1, 10**6), st.lists(st.tuples(vec, vec, st.floats(8, 2000)), min_size=1,
                                      max_size=8))
def test_any_views_round_trip(first: int, rows: list) -> None:
    rows = [r for r in rows if r[0] != r[1]]
    views = [View(first + i, o, v, f) for i, (o, v, f) in enumerate(rows)]
    if views:
        assert parse_views(views_text(views)) == views


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet="0123456789 .-+e#\nnaif,x", max_size=120))
def test_random_text_is_read_or_refused_with_a_position(text: str) -> None:
    exc = refusal_of(parse_views, text, "r.views", ViewFileError)
    assert exc is None or (exc.line >= 1 and exc.col >= 1)
