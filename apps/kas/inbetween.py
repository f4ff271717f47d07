"""The in-betweener (§3.1.2): frames between keyframes, vectorised with numpy.

Two keyframes: each pair of corresponding points follows the sample path fitted between them
(or a straight line), placed along it by the timing.  Several keyframes: an interpolating
spline through them, the timing applied within each pair.  Redundant collinear points are
dropped from the output frames.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from camlab88.apps.kas import correspond, kernels, pathfit, splines
from camlab88.apps.kas.files import SamplePath, Timing
from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from camlab88.apps.kas.timing import fractions
from camlab88.base import budget

TOL = 1e-9  # relative collinearity tolerance for dropping points


def _stack(matched: list[list[Chain]]) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[int]]:
    """keys (K, M, 2), colours (K, M), chain bounds (C + 1,), sections per chain."""
    keys = np.stack([np.concatenate([c.points for c in chains]) for chains in matched])
    cols = np.stack([np.concatenate([c.colours for c in chains]) for chains in matched])
    bounds = np.concatenate([[0], np.cumsum([len(c) for c in matched[0]])])
    sections = [c.section for c in matched[0]]
    return keys, cols, bounds, sections


def _frames(pos: np.ndarray, cols: np.ndarray, bounds: np.ndarray, sections: list[int],
            drop: bool) -> list[Drawing]:
    """Split (F, M, 2) positions and (F, M) colours into drawings of chains."""
    n_frames, m = pos.shape[:2]
    cols = np.ascontiguousarray(cols, dtype=np.int16)
    bounds = np.asarray(bounds, dtype=np.int64)
    if drop:
        pos = np.ascontiguousarray(pos)
        keep = kernels.keep_mask(pos, cols, bounds, TOL)
        # packed kept points; cut[f, j] = where chain j of frame f begins in them
        p_all, c_all, cut = kernels.compact(pos, cols, keep, bounds)
    else:
        p_all, c_all = pos.reshape(-1, 2), cols.reshape(-1)
        cut = np.arange(n_frames)[:, None] * m + bounds[None, :]
    cut = cut.tolist()
    n = len(sections)
    out = []
    for f in range(n_frames):
        b = cut[f]
        out.append(Drawing([Chain.raw(p_all[b[j]:b[j + 1]], c_all[b[j]:b[j + 1]], sections[j])
                            for j in range(n)]))
    return out


# What a point of a made frame costs: its position and pen (24 bytes), the path fit's and
# the redundant-point drop's copies, its chain, then its line when the sequence is written
POINT_FRAME_BYTES = 160


def check_cost(source: str, keys: list[Drawing], frames: int) -> None:
    """Refuse (base.budget) ``frames`` frames of ``keys``' points over the memory budget,
    before any frame is made."""
    points = max((k.n_points for k in keys), default=0)
    budget.check(source, points * frames * POINT_FRAME_BYTES,
                 f"{frames:,} frames of {points:,} points")


def frame_count(timing: Timing | None, frames: int | None, keys: int) -> int:
    """The frames :func:`inbetween` or :func:`inbetween_keys` will make."""
    d = len(fractions(timing, frames))
    return d if keys == 2 else (keys - 1) * (d - 1) + 1


def inbetween(a: Drawing, b: Drawing, frames: int | None = None,
              path: SamplePath | None = None, timing: Timing | None = None,
              missing: str = "copy-nearest", fit: str = pathfit.DEFAULT_FIT, drop: bool = True,
              fps: float = 25.0) -> AnimSequence:
    """Frames from ``a`` to ``b`` inclusive; ``frames`` counts both keyframes."""
    d = fractions(timing, frames)
    matched = correspond.match([a, b], missing)
    if not matched[0]:
        return AnimSequence([Drawing() for _ in d], fps)
    keys, cols, bounds, sections = _stack(matched)
    pos = pathfit.fit(keys[0], keys[1], d, path, fit)
    pos[0], pos[-1] = keys[0], keys[1]  # keyframes exactly as drawn, whatever the path
    second = np.arange(len(d)) >= (len(d) - 1) / 2
    colours = np.where(second[:, None], cols[1][None], cols[0][None])
    return AnimSequence(_frames(pos, colours, bounds, sections, drop), fps)


def inbetween_keys(keys: list[Drawing], frames: int, method: str = "catmull-rom",
                   timing: Timing | None = None, missing: str = "copy-nearest",
                   tension: float = 0.0, continuity: float = 0.0, bias: float = 0.0,
                   drop: bool = True, fps: float = 25.0,
                   progress: Callable[[int, int], None] | None = None) -> AnimSequence:
    """Frames through all ``keys``: ``frames`` per pair (both ends counted), shared keys once."""
    d = fractions(timing, frames)
    matched = correspond.match(keys, missing)
    if not matched[0]:
        return AnimSequence([Drawing() for _ in range((len(keys) - 1) * (len(d) - 1) + 1)], fps)
    stacked, cols, bounds, sections = _stack(matched)
    parts, colour_parts = [], []
    second = np.arange(len(d)) >= (len(d) - 1) / 2
    for i in range(len(keys) - 1):
        seg = splines.segment(stacked, i, d, method, tension, continuity, bias)
        seg[0], seg[-1] = stacked[i], stacked[i + 1]
        c = np.where(second[:, None], cols[i + 1][None], cols[i][None])
        if i:
            seg, c = seg[1:], c[1:]
        parts.append(seg)
        colour_parts.append(c)
        if progress:
            progress(i + 1, len(keys) - 1)
    pos = np.concatenate(parts)
    colours = np.concatenate(colour_parts)
    return AnimSequence(_frames(pos, colours, bounds, sections, drop), fps)
