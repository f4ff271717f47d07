"""Interpolation through several keyframes (§3.1.2): linear, Overhauser, Catmull-Rom,
Kochanek-Bartels; all interpolating (they pass through every keyframe), vectorised over
frames and points.  The ends use phantom keys reflected through the end keys."""

from __future__ import annotations

import numpy as np

METHODS = ("linear", "overhauser", "catmull-rom", "kochanek-bartels")


def _padded(keys: np.ndarray) -> np.ndarray:
    first = 2 * keys[0] - keys[1]
    last = 2 * keys[-1] - keys[-2]
    return np.concatenate([first[None], keys, last[None]])


def _hermite(p0, p1, m0, m1, u):
    u = u[:, None, None]
    u2, u3 = u * u, u * u * u
    return ((2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0
            + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * m1)


def _parabola(q0, q1, q2, s1, s2, s):
    """Lagrange parabola through q0@0, q1@s1, q2@s2, at s (arrays broadcast over points)."""
    l0 = (s - s1) * (s - s2) / (s1 * s2)
    l1 = s * (s - s2) / (s1 * (s1 - s2))
    l2 = s * (s - s1) / (s2 * (s2 - s1))
    return l0 * q0 + l1 * q1 + l2 * q2


def segment(keys: np.ndarray, i: int, u: np.ndarray, method: str = "catmull-rom",
            tension: float = 0.0, continuity: float = 0.0, bias: float = 0.0) -> np.ndarray:
    """Positions (F, M, 2) between key ``i`` and ``i + 1`` of ``keys`` (K, M, 2) at ``u`` (F,)."""
    if method not in METHODS:
        raise ValueError(f"interpolation must be one of {', '.join(METHODS)}")
    u = np.asarray(u, dtype=np.float64)
    p = _padded(np.asarray(keys, dtype=np.float64))
    pm, p0, p1, p2 = p[i], p[i + 1], p[i + 2], p[i + 3]
    if method == "linear":
        return p0[None] + u[:, None, None] * (p1 - p0)[None]
    if method == "catmull-rom":
        return _hermite(p0, p1, (p1 - pm) / 2, (p2 - p0) / 2, u)
    if method == "kochanek-bartels":
        # Kochanek & Bartels 1984: the segment leaves p0 along its outgoing ("source")
        # tangent and reaches p1 along p1's incoming ("destination") tangent.  With c = -1
        # both are the segment's own chord (straight lines, corners at the keys); with
        # c = +1 each is the chord on the far side of its key.
        t, c, b = tension, continuity, bias
        m0 = ((1 - t) * (1 + b) * (1 + c) / 2 * (p0 - pm)
              + (1 - t) * (1 - b) * (1 - c) / 2 * (p1 - p0))
        m1 = ((1 - t) * (1 + b) * (1 - c) / 2 * (p1 - p0)
              + (1 - t) * (1 - b) * (1 + c) / 2 * (p2 - p1))
        return _hermite(p0, p1, m0, m1, u)
    # Overhauser (Brewer & Anderson 1977): blend of the parabolas through (pm, p0, p1) and
    # (p0, p1, p2), each parameterised by chord length; degenerate chords fall back to equal
    # spacing, where the result equals Catmull-Rom.
    def chord(x, y):
        return np.hypot(*(y - x).T)[:, None]
    la, lb, lc = chord(pm, p0), chord(p0, p1), chord(p1, p2)
    tiny = 1e-12
    bad = (la < tiny) | (lb < tiny) | (lc < tiny)
    la, lb, lc = np.where(bad, 1.0, la), np.where(bad, 1.0, lb), np.where(bad, 1.0, lc)
    uu = u[:, None, None]
    left = _parabola(pm, p0, p1, la, la + lb, la + uu * lb)
    right = _parabola(p0, p1, p2, lb, lb + lc, uu * lb)
    return (1 - uu) * left + uu * right
