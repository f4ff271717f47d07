"""numba kernels for the in-betweener's hot loop: which points of every frame are redundant.

Same rule and the same floating-point expressions as ``model.redundant_mask`` (the numpy
reference, which the tests compare it with), in one pass over frames x points instead of a
dozen whole-array passes. Imported only for large in-betweens
(``camlab88.apps.kas.kernels`` chooses).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from camlab88.base.kernel_notice import announce_compiles

announce_compiles("KAS in-betweener", 1.0, __name__)  # cold compile time, measured


@njit(cache=True)
def keep_mask(points: np.ndarray, colours: np.ndarray, bounds: np.ndarray,
              tol: float) -> np.ndarray:
    f_n, n = points.shape[0], points.shape[1]
    keep = np.ones((f_n, n), dtype=np.bool_)
    tol2 = tol * tol
    for f in range(f_n):
        for j in range(bounds.shape[0] - 1):
            s, e = bounds[j], bounds[j + 1] - 1
            for i in range(s + 1, e + 1):
                dx = points[f, i, 0] - points[f, i - 1, 0]
                dy = points[f, i, 1] - points[f, i - 1, 1]
                l1 = dx * dx + dy * dy
                if l1 == 0.0:
                    keep[f, i] = False  # repeats the previous point
                    continue
                if i == e:
                    continue
                ex = points[f, i + 1, 0] - points[f, i, 0]
                ey = points[f, i + 1, 1] - points[f, i, 1]
                l2 = ex * ex + ey * ey
                if l2 == 0.0 or colours[f, i] != colours[f, i + 1]:
                    continue
                cross = dx * ey - dy * ex
                dot = dx * ex + dy * ey
                if cross * cross <= tol2 * l1 * l2 and dot > 0.0:
                    keep[f, i] = False
    return keep


@njit(cache=True)
def compact(points: np.ndarray, colours: np.ndarray, keep: np.ndarray,
            bounds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Kept points of all frames packed in order, and where each frame's chain j begins
    (``cut[f, j]``; ``cut[f, -1]`` is the end of frame f)."""
    f_n, n = keep.shape
    c_n = bounds.shape[0]
    total = 0
    for f in range(f_n):
        for i in range(n):
            if keep[f, i]:
                total += 1
    out_p = np.empty((total, 2), dtype=points.dtype)
    out_c = np.empty(total, dtype=colours.dtype)
    cut = np.empty((f_n, c_n), dtype=np.int64)
    k = 0
    for f in range(f_n):
        j = 0
        for i in range(n):
            while j < c_n and bounds[j] == i:
                cut[f, j] = k
                j += 1
            if keep[f, i]:
                out_p[k, 0] = points[f, i, 0]
                out_p[k, 1] = points[f, i, 1]
                out_c[k] = colours[f, i]
                k += 1
        while j < c_n:
            cut[f, j] = k
            j += 1
    return out_p, out_c, cut
