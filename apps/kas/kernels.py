"""The in-betweener's hot loop, which points of every frame are redundant, in numpy or numba.

Both paths give identical results (the same rule and floating-point expressions as
``model.redundant_mask``; tests/test_startup_paths.py compares them). numba is 4-6x faster
on a million points and more, but importing it and loading its cached kernels costs about
0.45 s of a process's start-up, more than numpy needs for a million points (0.08 s) -- so a
small in-between (every KAS command a user types) never imports numba and a large one uses
the compiled kernels: the choice is by size alone, never by what the process imported
before, so a result's path does not depend on what ran earlier (docs/perf/startup.md).
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas.model import redundant_mask

NUMBA_FROM_POINTS = 2_000_000  # frames x points from which numba pays for its own start-up


def use_numba(points: np.ndarray) -> bool:
    """Whether the compiled kernels pay for an array of (frames, points, 2)."""
    size = points.shape[0] * points.shape[1]
    return size >= NUMBA_FROM_POINTS


def keep_mask(points: np.ndarray, colours: np.ndarray, bounds: np.ndarray,
              tol: float) -> np.ndarray:
    """(F, n) bool, True = keep: the point is neither a repeat nor the middle of a straight,
    one-coloured run of its chain (chains split at ``bounds``)."""
    if use_numba(points):
        from camlab88.apps.kas import kernels_jit

        return kernels_jit.keep_mask(points, colours, bounds, tol)
    return redundant_mask(points, colours, tol, bounds)


def compact(points: np.ndarray, colours: np.ndarray, keep: np.ndarray,
            bounds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Kept points of all frames packed in order, and where each frame's chain j begins
    (``cut[f, j]``; ``cut[f, -1]`` is the end of frame f)."""
    if use_numba(points):
        from camlab88.apps.kas import kernels_jit

        return kernels_jit.compact(points, colours, keep, bounds)
    return compact_numpy(points, colours, keep, bounds)


def compact_numpy(points: np.ndarray, colours: np.ndarray, keep: np.ndarray,
                  bounds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``compact`` in whole-array numpy operations."""
    f_n, n = keep.shape
    before = np.zeros((f_n, n + 1), dtype=np.int64)  # kept points of frame f before index i
    np.cumsum(keep, axis=1, out=before[:, 1:])
    frame_start = np.zeros(f_n, dtype=np.int64)
    np.cumsum(before[:-1, n], out=frame_start[1:])
    cut = frame_start[:, None] + before[:, np.asarray(bounds, dtype=np.int64)]
    return points[keep], colours[keep], cut
