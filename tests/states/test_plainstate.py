"""base.plainstate: a declared schema's values round trip, and what a state may not hold is
refused with one line naming where it is."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from camlab88.base.plainstate import (
    Array,
    Blob,
    Bool,
    Choice,
    Float,
    Frac,
    Int,
    JsonText,
    ListOf,
    Opt,
    Record,
    StateValueError,
    Str,
    Tuple,
    decode,
    encode,
)

SCHEMA = Record(n=Int(0, 9), x=Float(), ok=Bool(), name=Str(8), mode=Choice(("a", "b")),
                t=Frac(nonnegative=True), maybe=Opt(Int()), xs=ListOf(Tuple((Int(), Int())), 3),
                grid=Array("<i2", 2, 100), raw=Blob(16), doc=JsonText(max_depth=3))
VALUES = {"n": 3, "x": 0.5, "ok": True, "name": "ab", "mode": "b", "t": Fraction(7, 3),
          "maybe": None, "xs": [(1, 2)], "grid": np.arange(6, dtype="<i2").reshape(2, 3),
          "raw": b"\x00\x01", "doc": {"k": [1, 2]}}


def _round(values: dict) -> dict:
    parts: dict[str, bytes] = {}
    return decode(SCHEMA, encode(SCHEMA, values, parts), parts)


def test_values_round_trip() -> None:
    back = _round(VALUES)
    assert back["grid"].dtype == np.dtype("<i2") and np.array_equal(back["grid"], VALUES["grid"])
    assert {k: v for k, v in back.items() if k != "grid"} == \
        {k: v for k, v in VALUES.items() if k != "grid"}


@pytest.mark.parametrize("field, bad, where", [
    ("n", 10, "state.n"), ("n", True, "state.n"), ("n", 1.0, "state.n"),
    ("x", float("inf"), "state.x"), ("name", "x" * 9, "state.name"),
    ("mode", "c", "state.mode"), ("t", [1, 0], "state.t"), ("t", [-1, 2], "state.t"),
    ("t", [10**300, 1], "state.t"), ("t", "1e999999999", "state.t"),
    ("xs", [[1, 2]] * 4, "state.xs"), ("xs", [[1]], "state.xs[0]"),
    ("maybe", {"O": "os:system"}, "state.maybe"),
    ("grid", ["a0", [10**6, 10**6]], "state.grid"), ("grid", ["a0", [2, 4]], "state.grid"),
    ("grid", ["nothing", [2, 3]], "state.grid"), ("raw", "nothing", "state.raw"),
])
def test_a_value_that_does_not_fit_is_refused_naming_where(field: str, bad: object,
                                                           where: str) -> None:
    parts: dict[str, bytes] = {}
    tree = encode(SCHEMA, VALUES, parts)
    tree[field] = bad
    with pytest.raises(StateValueError) as exc:
        decode(SCHEMA, tree, parts)
    assert str(exc.value).startswith(where) and "\n" not in str(exc.value)


def test_fields_are_exactly_the_declared_ones_and_json_is_bounded() -> None:
    parts: dict[str, bytes] = {}
    tree = encode(SCHEMA, VALUES, parts)
    with pytest.raises(StateValueError, match="not the declared ones"):
        decode(SCHEMA, dict(tree, extra=1), parts)
    parts[tree["doc"]] = b"[[[[[1]]]]]"
    with pytest.raises(StateValueError, match="nested deeper than 3"):
        decode(SCHEMA, tree, parts)


def test_only_plain_dtypes_may_be_declared() -> None:
    with pytest.raises(TypeError):
        Array("O", 1)
    with pytest.raises(TypeError):
        Array("<c16", 1)
