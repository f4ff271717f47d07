"""The compiler kernel's hand-written stand-ins for numpy calls (kept because numba compiles
them in a fraction of the time) give numpy's results."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.emulator.rainbow import _kernels


@settings(deadline=None)  # the first example compiles or loads the kernels
@given(st.lists(st.integers(-1000, 1000) | st.integers(0, 5), max_size=200))
def test_unique_is_numpys_unique(values: list[int]) -> None:
    a = np.array(values, np.int64)
    assert np.array_equal(_kernels._unique(a.copy()), np.unique(a))


@settings(deadline=None)
@given(st.integers(1, 40), st.integers(0, 100))
def test_grow_keeps_the_rows_and_makes_room(rows: int, need: int) -> None:
    a = np.arange(rows * 5, dtype=np.int64).reshape(rows, 5)
    b = _kernels._grow(a, need)
    assert b.shape[0] >= need and b.shape[1] == 5
    assert np.array_equal(b[:rows], a)
