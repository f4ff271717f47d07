"""The rules' lookup of small message values (apps/ca/tables.py) is the first matching
interpretation line of each value, as the rule language defines it, whatever mix of exact
values, #B patterns and ranges the lines are; and the distinct coordinates the bounding box
reads (apps/ca/universe.py) are numpy's."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca.rules import parse_rules
from camlab88.apps.ca.tables import LOOKUP_SIZE, compile_rules
from camlab88.apps.ca.universe import distinct

# values near the table's end and beyond it, where a range is cut off
_VALUES = st.one_of(st.integers(0, 40), st.integers(LOOKUP_SIZE - 3, LOOKUP_SIZE + 3),
                    st.integers(0, (1 << 32) - 1))


@st.composite
def _line(draw: st.DrawFn) -> str:
    kind = draw(st.sampled_from(("exact", "pattern", "range")))
    form = draw(st.integers(0, 3))
    if kind == "exact":
        return f"{draw(_VALUES)} {form}"
    if kind == "pattern":
        bits = draw(st.text("01?", min_size=1, max_size=18))
        return f"#B{bits}{'?' if '?' not in bits else ''} {form}"
    lo, hi = sorted((draw(_VALUES), draw(_VALUES)))
    return f"R {lo} {hi} {form}"


@settings(max_examples=200, deadline=None)
@given(st.lists(_line(), min_size=1, max_size=12))
def test_the_lookup_is_the_first_matching_line_of_every_value(lines: list[str]) -> None:
    rules = parse_rules("1 1 1 1 1 . +1 . +1 +2 +1 . +1 . $ " + " ".join(lines))
    lookup = compile_rules(rules).lookup
    values = np.arange(LOOKUP_SIZE, dtype=np.int64)
    want = np.full(LOOKUP_SIZE, -1, np.int64)
    for i, it in reversed(list(enumerate(rules.interpretations))):  # every value, each line
        hit = {0: values == it.a, 1: (values & it.a) == it.b,
               2: (values >= it.a) & (values <= it.b)}[it.kind]
        want[hit] = i
    assert np.array_equal(lookup, want)
    for v in (0, 1, 7, LOOKUP_SIZE - 1):  # and the language's own definition agrees
        first = next((i for i, it in enumerate(rules.interpretations) if it.matches(v)), -1)
        assert lookup[v] == first


@settings(max_examples=100, deadline=None)
@given(st.lists(st.integers(0, 65535), max_size=40))
def test_distinct_is_numpys_unique(values: list[int]) -> None:
    a = np.array(values, np.int64)
    got = distinct(a)
    assert got.dtype == a.dtype and np.array_equal(got, np.unique(a))
