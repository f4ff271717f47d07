"""Fill any continuous boundary (thesis §3.3, last paragraph: "it would be easier to use if
a method were found to allow any continuous boundary to be used for filling"): regions are
the planar faces of the arrangement of all the frame's lines (plus gap-closing segments),
and a region chosen in one frame is found again in every other frame through the
in-betweener's point correspondence.

Correspondence (reconstructed): chain j of one frame is chain j of every other (the
in-betweener matches chains by drawing order, §3.1.2), and along a chain points correspond
by fraction of arc length (the in-betweener moves corresponding points, and dropping
redundant points changes indices but not where the line runs).  A region is described by
which stretches of which chains bound it (its *signature*); in another frame the chosen
point is carried along with those stretches, and the face there whose signature agrees
best is taken.  If none agrees well enough the frame is reported, not guessed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.kas.model import Drawing
from camlab88.apps.kas.paint import areas, seeds, shape, vector

BINS = 32          # stretches per chain in a signature
AGREE = 0.3        # least Jaccard agreement of signatures to accept a face


@dataclass
class Arrangement:
    """One frame's walls (area pixels), their faces, and who owns each wall pixel."""

    walls: list[np.ndarray]
    gaps: list[np.ndarray]
    faces: seeds.Faces
    owner: np.ndarray   # chain index + 1 per window pixel, 0 = no chain
    param: np.ndarray   # arc-length bin of that chain there
    chains: list[np.ndarray]  # chain points in inches
    arcs: list[np.ndarray]    # their arc-length fractions at the points


def _arc(points: np.ndarray) -> np.ndarray:
    seg = np.hypot(*np.diff(points, axis=0).T) if len(points) > 1 else np.zeros(0)
    cum = np.concatenate([[0.0], np.cumsum(seg)])
    return cum / cum[-1] if cum[-1] > 0 else cum


def arrangement(frame: Drawing, gap: float) -> Arrangement:
    chains = [c.points for c in frame.chains if len(c)]
    walls = [areas.dedup(areas.to_px(p)) for p in chains]
    gaps = [areas.dedup(areas.to_px(g)) for g in shape.gap_segments(frame, gap)]
    f = seeds.faces(walls + gaps)
    owner = np.zeros(f.labels.shape, dtype=np.int32)
    param = np.zeros(f.labels.shape, dtype=np.int32)
    ox, oy = f.origin
    for j, px in enumerate(walls):
        x, y, seg = vector.polyline_pixels(px)
        t = _arc(px.astype(np.float64)) if len(px) > 1 else np.zeros(1)
        owner[y - oy, x - ox] = j + 1
        param[y - oy, x - ox] = np.minimum((t[np.minimum(seg, len(t) - 1)] * BINS), BINS - 1)
    return Arrangement(walls, gaps, f, owner, param, chains, [_arc(p) for p in chains])


def signature(arr: Arrangement, k: int) -> set[tuple[int, int]]:
    """(chain, stretch) of every chain pixel next to face ``k``."""
    m = arr.faces.labels == k
    near = np.zeros_like(m)
    near[1:] |= m[:-1]
    near[:-1] |= m[1:]
    near[:, 1:] |= m[:, :-1]
    near[:, :-1] |= m[:, 1:]
    near &= arr.owner > 0
    return set(zip(arr.owner[near].tolist(), arr.param[near].tolist(), strict=True))


def _at(arr: Arrangement, j: int, t: np.ndarray) -> np.ndarray:
    """Points at arc fractions ``t`` along chain j (0-based), (len(t), 2)."""
    a, c = arr.arcs[j], arr.chains[j]
    return np.column_stack([np.interp(t, a, c[:, 0]), np.interp(t, a, c[:, 1])])


def carry(point: tuple[float, float], sig: set[tuple[int, int]], src: Arrangement,
          dst: Arrangement) -> tuple[float, float]:
    """Move ``point`` (inches) with the mean motion of the chain stretches bounding it."""
    by_chain: dict[int, list[float]] = {}
    for j, b in sorted(sig):
        if j - 1 < len(dst.chains):
            by_chain.setdefault(j - 1, []).append((b + 0.5) / BINS)
    if not by_chain:
        return point
    moves = np.concatenate([_at(dst, j, np.array(t)) - _at(src, j, np.array(t))
                            for j, t in by_chain.items()])
    d = moves.mean(axis=0)
    return point[0] + float(d[0]), point[1] + float(d[1])


def face_at(arr: Arrangement, point: tuple[float, float]) -> int:
    """The bounded face containing ``point`` (inches), or 0 (on a line / outside)."""
    px = areas.to_px(np.array([point]))[0]
    k = arr.faces.label_at(int(px[0]), int(px[1]))
    return k if k > 0 and arr.faces.bounded[k] else 0


def _jaccard(a: set, b: set) -> float:
    return len(a & b) / len(a | b) if a or b else 0.0


def follow(sig: set[tuple[int, int]], point: tuple[float, float], src: Arrangement,
           dst: Arrangement) -> int:
    """The face of ``dst`` that is the region ``sig`` of ``src``, or 0 if none agrees."""
    k = face_at(dst, carry(point, sig, src, dst))
    if k and _jaccard(sig, signature(dst, k)) >= 0.5:
        return k
    f = dst.faces
    scores = [(_jaccard(sig, signature(dst, c)), -c) for c in range(1, f.n + 1) if f.bounded[c]]
    if not scores:
        return 0
    best, neg = max(scores)
    return -neg if best >= AGREE else 0
