"""camlab88.base.aot_args: signatures read without numba, and an ahead-of-time kernel refusing
arguments its one compiled signature would misread."""

from __future__ import annotations

import numpy as np
import pytest
from camlab88.base.aot_args import Arg, checked, parse


def test_signatures_are_read() -> None:
    args = parse("UniTuple(int64[:], 2)(int64[:], uint8[:, ::1], intp, boolean, float64)")
    assert args == (Arg("int64[:]", np.dtype(np.int64), 1, False),
                    Arg("uint8[:, ::1]", np.dtype(np.uint8), 2, True),
                    Arg("intp", np.dtype(np.intp)), Arg("boolean", None),
                    Arg("float64", np.dtype(np.float64)))
    assert parse("none()") == ()


@pytest.mark.parametrize("bad", ["int64", "int64(complex128)", "int64(int64[::1, :])",
                                 "int64(Record(x))", "int64(int64[:]"])
def test_other_signatures_are_refused(bad: str) -> None:
    with pytest.raises(ValueError):
        parse(bad)


def _kernel(*args):
    return len(args)


def test_matching_arguments_pass_through() -> None:
    f = checked(_kernel, "k", "int64(int64[:], uint8[:, ::1], int64, float64, boolean)")
    grid = np.zeros((3, 4), np.uint8)
    assert f(np.arange(5)[::2], grid, np.int64(3), 2, None) == 5
    assert f.__name__ == "k" and f.__wrapped__ is _kernel


@pytest.mark.parametrize("args, wrong", [
    ((np.arange(5, dtype=np.int32), np.zeros((3, 4), np.uint8), 1), "argument 1 is int32[::1]"),
    ((np.arange(5), np.zeros((3, 4), np.uint8).T, 1), "argument 2 is uint8[:, :]"),
    ((np.arange(5), np.zeros(4, np.uint8), 1), "argument 2 is uint8[::1]"),
    ((np.arange(5), np.zeros((3, 4), np.uint8), 1.5), "argument 3 is float"),
])
def test_mismatches_raise_before_the_call(args: tuple, wrong: str) -> None:
    f = checked(_kernel, "k", "int64(int64[:], uint8[:, ::1], int64)")
    with pytest.raises(TypeError, match=r"ahead-of-time kernel k .*" + wrong.replace(
            "[", r"\[").replace("]", r"\]")):
        f(*args)
