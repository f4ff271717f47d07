"""The Tripos ReadArgs reader (camlab88.tripos_args) on section 7.3.1's template."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from camlab88.tripos_args import TriposArgsError, parse_template, read_args

T = "Log/k,RecordPansAndZooms/s,Checkpoint,Script/k,ReplayPansAndZooms/s"


def test_template_items_and_qualifiers() -> None:
    items = parse_template(T)
    assert [(i.keyword, i.qualifier) for i in items] == [
        ("Log", "k"), ("RecordPansAndZooms", "s"), ("Checkpoint", ""), ("Script", "k"),
        ("ReplayPansAndZooms", "s")]
    with pytest.raises(ValueError, match="/a not supported"):
        parse_template("From/a")


def test_keywords_switches_and_positional() -> None:
    assert read_args(["log", "x", "50", "recordpansandzooms"], T) == {
        "Log": "x", "Checkpoint": "50", "RecordPansAndZooms": True}
    assert read_args(["Checkpoint=7", "Script", "old.log"], T) == {
        "Checkpoint": "7", "Script": "old.log"}
    assert read_args([], T) == {}
    # a /k item is never filled by position: the word goes to Checkpoint
    assert read_args(["x.log"], T) == {"Checkpoint": "x.log"}
    with pytest.raises(TriposArgsError, match="argument 2 .'y'.: not a keyword"):
        read_args(["x", "y"], T)


words = st.lists(st.text(st.characters(blacklist_categories=("Cs",)), max_size=12),
                 max_size=8)


@given(words)
def test_any_words_give_values_or_a_clear_error(ws: list[str]) -> None:
    try:
        got = read_args(ws, T)
    except TriposArgsError as exc:
        assert str(exc).startswith("argument ")
        return
    assert set(got) <= {"Log", "RecordPansAndZooms", "Checkpoint", "Script",
                        "ReplayPansAndZooms"}
    assert all(v is True for k, v in got.items() if k.endswith("Zooms"))
