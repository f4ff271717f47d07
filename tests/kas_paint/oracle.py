"""An oracle for tests: which pixels lie inside a closed shape, from the geometry (distances
to the true segments) and an exterior flood — independent of the host's DDA copy, its
component labelling and the terminal's filler."""

from __future__ import annotations

import numpy as np


def seg_distance(polys: list[np.ndarray], xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """Distance from every point (xs, ys) to the nearest segment of ``polys``."""
    px = np.stack([xs.ravel(), ys.ravel()], axis=1).astype(np.float64)
    best = np.full(len(px), np.inf)
    for poly in polys:
        p = np.asarray(poly, dtype=np.float64)
        if len(p) == 1:
            p = np.concatenate([p, p])
        for a, b in zip(p[:-1], p[1:], strict=True):
            ab = b - a
            ll = ab @ ab
            t = np.clip(((px - a) @ ab) / ll, 0, 1) if ll > 0 else np.zeros(len(px))
            np.minimum(best, np.hypot(*(a + t[:, None] * ab - px).T), out=best)
    return best.reshape(xs.shape)


def _spread_rows(free: np.ndarray, ext: np.ndarray) -> np.ndarray:
    """Spread ``ext`` along each row through runs of free cells."""
    h, w = free.shape
    run = np.cumsum(np.concatenate([np.ones((h, 1), bool), free[:, 1:] != free[:, :-1]],
                                   axis=1), axis=1) + (np.arange(h) * (w + 1))[:, None]
    hit = np.zeros(run.max() + 1, dtype=bool)
    hit[run[ext & free]] = True
    return hit[run] & free


def exterior(free: np.ndarray) -> np.ndarray:
    """Free cells 4-connected to the border (rows and columns in turn until stable)."""
    ext = np.zeros_like(free)
    ext[0], ext[-1], ext[:, 0], ext[:, -1] = free[0], free[-1], free[:, 0], free[:, -1]
    while True:
        new = _spread_rows(free.T, _spread_rows(free, ext).T).T
        if np.array_equal(new, ext):
            return ext
        ext = new


def classify(polys: list[np.ndarray], box: tuple[int, int, int, int]
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Over pixels x0..x1, y0..y1 (array [y - y0, x - x0]): (inside, sure, distance).
    ``inside`` = in a bounded face; ``sure`` = far (> 1.5 px) from every segment and the
    answer is the same with thin (0.5) and thick (0.75) geometric walls."""
    x0, y0, x1, y1 = box
    ys, xs = np.mgrid[y0:y1 + 1, x0:x1 + 1]
    d = seg_distance(polys, xs, ys)
    thin = ~exterior(d > 0.5) & (d > 0.5)
    thick = ~exterior(d > 0.75) & (d > 0.75)
    return thick, (d > 1.5) & (thin == thick), d
