"""Fitting the animator's sample path between corresponding points (§3.1.2, figure 3.6).

The thesis says the one hand-drawn path is "stretched, translated and reflected" so that its
ends meet each pair of corresponding points; it gives no formula.  Reconstruction (``mode=
"stretch"``, the default): the fit is done in the chord's own frame, so the path keeps its
shape.  With the path's chord ``c = end - start`` and a point's displacement ``δ = b - a``
(as complex numbers), a path point ``p`` at excursion ``q = p - start`` becomes

    a + δ · (q / c)            when  c·δ >= 0  (rotate + uniform scale |δ|/|c|)
    a + δ · conj(q / c)        when  c·δ <  0  (the same, mirrored across the chord)

i.e. the along-chord and perpendicular components are both scaled by |δ|/|c|, turned onto δ,
and reflected when the point moves "backwards" relative to the drawn chord, so that a path
drawn as an upward arch from left to right is still an upward arch for a point moving right
to left (the thesis's "reflected").  The ends land exactly on ``a`` and ``b``.  A point that
does not move (δ = 0) stays put.  A closed path (no chord) cannot be scaled: its excursion is
kept as drawn and the displacement is spread along it in proportion to distance.
``mode="similarity"`` is the same without the reflection (pure rotation + uniform scale).

An earlier version stretched x and y independently by δ/c per axis; a path with almost level
ends then blew its vertical excursion up by δy/cy (in-betweens far off the screen), so it was
replaced by this shape-keeping fit.
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
    c = complex(*chord)
    if abs(c) <= eps:
        if mode == "similarity":
            raise ValueError("a closed sample path cannot be fitted by similarity")
        return a[None] + q[:, None, :] + d[:, None, None] * delta[None]
    w = ((q[:, 0] + 1j * q[:, 1]) / c)[:, None]        # (F, 1) excursion in chord units
    zd = (delta[:, 0] + 1j * delta[:, 1])[None]         # (1, M)
    if mode == "stretch":
        backwards = (delta @ chord) < 0                 # (M,) reflect these points' paths
        w = np.where(backwards[None], np.conj(w), w)
    z = (a[:, 0] + 1j * a[:, 1])[None] + w * zd
    return np.stack([z.real, z.imag], axis=-1)
