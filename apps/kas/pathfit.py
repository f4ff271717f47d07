"""Fitting the animator's sample path between corresponding points (§3.1.2, figure 3.6).

The thesis: the one hand-drawn path is "translated, stretched and reflected as necessary"
until its ends meet each pair of corresponding points; it gives no formula.  With the path's
chord ``c = end - start``, a point's displacement ``δ = b - a`` and a path point's excursion
``q = p - start``, three fits are offered (``FIT_MODES``):

``axis-stretch`` — the thesis's words taken literally: x and y are stretched independently,
    ``a + (δx/cx·qx, δy/cy·qy)``; a negative ratio mirrors that axis (the "reflected"), and
    there is no rotation.  Written as ``a + t·δ + s·(q - t·c)`` (``t`` the distance fraction,
    ``s = δ/c`` per axis) it is the same formula, and the ends land exactly whatever ``s``.
    The literal ratio blows up when the chord is almost level or almost upright (``cy`` or
    ``cx`` near 0: a path whose ends are 0.03" apart in y stretched its excursion 30 times
    over).  So on an axis whose chord component is under ``DEGENERATE`` (a quarter) of the
    chord's length, ``f = DEGENERATE·|c|``, the ratio is blended towards the uniform scale
    ``u = |δ|/|c|`` (unmirrored) with weight ``w = (c_axis/f)²``:
    ``s = w·δ/c + (1 - w)·u = δ·c/f² + (1 - w)·u``.  It is continuous, equal to the
    literal ratio from ``f`` up, never more than ``|δ|/f + u`` across the axis, and a level
    chord (``cy = 0``) keeps its drawn arch at the uniform scale instead of 0/0.
``similarity-reflect`` (ours, the default; formerly called ``stretch``) — fitted in the
    chord's own frame so the path keeps its shape: rotated onto δ, scaled uniformly by
    ``|δ|/|c|`` along and across alike, and reflected across the chord when the point moves
    "backwards" (``c·δ < 0``), so an upward arch drawn left to right stays an upward arch
    for a point moving right to left.  In complex numbers ``a + δ·(q/c)`` or
    ``a + δ·conj(q/c)``.
``similarity`` (ours) — the same, never reflected (rotation and uniform scale only).

The default is ours because it is the one fit that keeps the drawn path's shape for every
direction of motion: under the literal reading a point moving parallel to an axis the chord
is not parallel to is stretched by 0 across that axis and loses the path's curve entirely.
``stretch``, the old name of ``similarity-reflect``, is still accepted (it never stretched
per axis, hence the new name).  A point that does not move (δ = 0) stays put.  A closed path
(no chord) cannot be scaled: its excursion is kept as drawn and the displacement is spread
along it in proportion to distance (``axis-stretch`` and ``similarity-reflect``).
"""

from __future__ import annotations

import os

import numpy as np

from camlab88.apps.kas.files import KasFileError, SamplePath, load_path

FIT_MODES = ("similarity-reflect", "axis-stretch", "similarity")
ALIASES = {"stretch": "similarity-reflect"}  # the name used before the thesis's mode existed
FIT_CHOICES = FIT_MODES + tuple(ALIASES)
DEFAULT_FIT = "similarity-reflect"
DEGENERATE = 0.25  # axis-stretch: chord components under this fraction of |c| are blended
MIN_LENGTH = 1e-6  # inches: a path shorter than this is a slip of the stylus, not a path


def canonical(mode: str) -> str:
    """The mode's own name (``stretch`` -> ``similarity-reflect``)."""
    mode = ALIASES.get(mode, mode)
    if mode not in FIT_MODES:
        raise ValueError(f"fit mode must be one of {', '.join(FIT_CHOICES)}, not {mode!r}")
    return mode


def check(path: SamplePath) -> None:
    """A usable path has at least two points and some length."""
    p = path.points
    if len(p) < 2:
        raise ValueError(f"a sample path needs at least two points (this one has {len(p)})")
    if not np.hypot(*np.diff(p, axis=0).T).sum() >= MIN_LENGTH:
        raise ValueError("the sample path has no length (its points lie within a millionth "
                         "of an inch)")


def load_checked(file: str | os.PathLike[str]) -> SamplePath:
    """Read a path file and check it can be fitted; errors name the file and the line of
    its ``points`` count (``points 0`` must be this error, not an IndexError later)."""
    path = load_path(file)
    try:
        check(path)
    except ValueError as exc:
        raise KasFileError(file, _points_line(file), str(exc)) from None
    return path


def _points_line(file: str | os.PathLike[str]) -> int:
    with open(file, encoding="utf-8", errors="replace") as f:
        for no, line in enumerate(f, 1):
            if line.split()[:1] == ["points"]:
                return no
    return 1  # pragma: no cover - load_path has already required the line


def point_at(path: SamplePath, d: np.ndarray) -> np.ndarray:
    """Points at fractions ``d`` of the path's length (extrapolated linearly past the ends)."""
    check(path)
    p = path.points
    seg = np.hypot(*np.diff(p, axis=0).T)
    cum = np.concatenate([[0.0], np.cumsum(seg)])
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


def axis_scales(chord: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """(M, 2) per-axis stretch factors of ``axis-stretch``: δ/c, blended towards the
    uniform scale |δ|/|c| on an axis where |c_axis| < DEGENERATE·|c| (see the module)."""
    length = float(np.hypot(*chord))
    floor = DEGENERATE * length
    uniform = np.hypot(*delta.T)[:, None] / length                # (M, 1)
    w = np.minimum(1.0, (chord / floor) ** 2)                     # (2,) 1 = literal
    literal = delta / np.where(w < 1, 1.0, chord)                 # δ/c where c is not small
    # w·δ/c = δ·c/floor²: the literal ratio's share is at most |δ|/floor and 0 at c = 0
    return np.where(w < 1, delta * chord / floor**2 + (1 - w) * uniform, literal)


def fit(a: np.ndarray, b: np.ndarray, d: np.ndarray, path: SamplePath | None = None,
        mode: str = DEFAULT_FIT) -> np.ndarray:
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
    mode = canonical(mode)
    check(path)
    p0, pn = path.points[0], path.points[-1]
    q = point_at(path, d) - p0                      # (F, 2) path excursion from its start
    chord = pn - p0
    extent = float(np.hypot(*(path.points.max(0) - path.points.min(0))))
    if np.hypot(*chord) <= 1e-9 * max(extent, 1e-300):
        if mode == "similarity":
            raise ValueError("a closed sample path cannot be fitted by similarity")
        return a[None] + q[:, None, :] + d[:, None, None] * delta[None]
    if mode == "axis-stretch":
        excursion = q - d[:, None] * chord[None]     # (F, 2) off the straight chord
        s = axis_scales(chord, delta)                # (M, 2)
        return a[None] + d[:, None, None] * delta[None] + excursion[:, None, :] * s[None]
    c = complex(*chord)
    w = ((q[:, 0] + 1j * q[:, 1]) / c)[:, None]        # (F, 1) excursion in chord units
    zd = (delta[:, 0] + 1j * delta[:, 1])[None]         # (1, M)
    if mode == "similarity-reflect":
        backwards = (delta @ chord) < 0                 # (M,) reflect these points' paths
        w = np.where(backwards[None], np.conj(w), w)
    z = (a[:, 0] + 1j * a[:, 1])[None] + w * zd
    return np.stack([z.real, z.imag], axis=-1)
