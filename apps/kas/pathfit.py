"""Fitting the animator's sample path between corresponding points (§3.1.2, figure 3.6).

The one hand-drawn path is stretched, translated and reflected so that its ends meet each
pair of corresponding points.  "Stretch" is taken per axis (x and y scale independently, a
negative scale being the reflection); the thesis lists no rotation.  When the path's chord
has no extent along an axis the scale is undefined there: the path's own excursion along that
axis is kept and the displacement is spread along the path in proportion to distance
(reconstruction).  ``mode="similarity"`` (rotate + uniform scale) is offered as an option.
"""

from __future__ import annotations

import numpy as np

from apps.kas.files import SamplePath

FIT_MODES = ("stretch", "similarity")


def point_at(path: SamplePath, d: np.ndarray) -> np.ndarray:
    """Points at fractions ``d`` of the path's length (extrapolated linearly past the ends)."""
    p = path.points
    if len(p) < 2:
        raise ValueError("a sample path needs at least two points")
    seg = np.hypot(*np.diff(p, axis=0).T)
    cum = np.concatenate([[0.0], np.cumsum(seg)])
    if cum[-1] <= 0:
        raise ValueError("the sample path has no length")
    s = np.asarray(d, dtype=np.float64) * cum[-1]
    x = np.interp(s, cum, p[:, 0])
    y = np.interp(s, cum, p[:, 1])
    # Timing curves may overshoot the ends; carry on along the end segments.
    lo, hi = s < 0, s > cum[-1]
    if lo.any():
        v = (p[1] - p[0]) / max(seg[0], 1e-300)
        x[lo], y[lo] = p[0, 0] + v[0] * s[lo], p[0, 1] + v[1] * s[lo]
    if hi.any():
        v = (p[-1] - p[-2]) / max(seg[-1], 1e-300)
        x[hi] = p[-1, 0] + v[0] * (s[hi] - cum[-1])
        y[hi] = p[-1, 1] + v[1] * (s[hi] - cum[-1])
    return np.column_stack([x, y])


def fit(a: np.ndarray, b: np.ndarray, d: np.ndarray, path: SamplePath | None = None,
        mode: str = "stretch") -> np.ndarray:
    """Positions (F, M, 2) of points going from ``a`` (M, 2) to ``b`` (M, 2).

    ``d`` (F,) are the frames' distance fractions.  Without a path the points move in
    straight lines.
    """
    a = np.asarray(a, dtype=np.float64)
    b = np.asarray(b, dtype=np.float64)
    d = np.asarray(d, dtype=np.float64)
    delta = b - a
    if path is None:
        return a[None] + d[:, None, None] * delta[None]
    if mode not in FIT_MODES:
        raise ValueError(f"fit mode must be one of {', '.join(FIT_MODES)}")
    p0, pn = path.points[0], path.points[-1]
    q = point_at(path, d) - p0                      # (F, 2) path excursion from its start
    chord = pn - p0
    extent = float(np.hypot(*(path.points.max(0) - path.points.min(0))))
    eps = 1e-9 * max(extent, 1e-300)
    if mode == "similarity":
        c = complex(*chord)
        if abs(c) <= eps:
            raise ValueError("a closed sample path cannot be fitted by similarity")
        zq = (q[:, 0] + 1j * q[:, 1])[:, None]
        z = (a[:, 0] + 1j * a[:, 1])[None] + zq * ((delta[:, 0] + 1j * delta[:, 1]) / c)[None]
        return np.stack([z.real, z.imag], axis=-1)
    out = np.empty((len(d), len(a), 2))
    for ax in range(2):
        if abs(chord[ax]) > eps:
            out[..., ax] = a[None, :, ax] + q[:, None, ax] * (delta[None, :, ax] / chord[ax])
        else:
            out[..., ax] = a[None, :, ax] + q[:, None, ax] + d[:, None] * delta[None, :, ax]
    return out
