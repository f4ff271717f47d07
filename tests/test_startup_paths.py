"""The KAS in-betweener's numpy and numba paths give identical results (apps/kas/kernels.py
picks numpy for small in-betweens so a command never pays numba's start-up for them)."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.kas import kernels, kernels_jit


@st.composite
def frames(draw: st.DrawFn) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    f_n = draw(st.integers(1, 4))
    n = draw(st.integers(1, 12))
    grid = st.integers(-2, 2)  # few values: repeats and straight runs are common
    pts = np.array(draw(st.lists(grid, min_size=f_n * n * 2, max_size=f_n * n * 2)),
                   dtype=np.float64).reshape(f_n, n, 2)
    cols = np.array(draw(st.lists(st.integers(0, 1), min_size=f_n * n, max_size=f_n * n)),
                    dtype=np.int16).reshape(f_n, n)
    inner = draw(st.lists(st.integers(1, n - 1), max_size=3)) if n > 1 else []
    bounds = np.array(sorted({0, n, *inner}), dtype=np.int64)
    return np.ascontiguousarray(pts), cols, bounds


@settings(max_examples=150, deadline=None)
@given(frames())
def test_numpy_and_numba_paths_agree(case: tuple[np.ndarray, np.ndarray, np.ndarray]) -> None:
    pts, cols, bounds = case
    fast = kernels_jit.keep_mask(pts, cols, bounds, 1e-9)
    assert np.array_equal(kernels.keep_mask(pts, cols, bounds, 1e-9), fast)
    jit = kernels_jit.compact(pts, cols, fast, bounds)
    ours = kernels.compact_numpy(pts, cols, fast, bounds)
    for a, b in zip(jit, ours, strict=True):
        assert a.dtype == b.dtype and np.array_equal(a, b)


def test_small_inbetweens_stay_in_numpy() -> None:
    """By size alone: numba is loaded in this process (the test above), and a small
    in-between still takes numpy."""
    import sys

    assert "numba" in sys.modules
    assert not kernels.use_numba(np.zeros((20, 500, 2)))
    assert not kernels.use_numba(np.zeros((1, kernels.NUMBA_FROM_POINTS - 1, 2)))
    assert kernels.use_numba(np.zeros((1, kernels.NUMBA_FROM_POINTS, 2)))
