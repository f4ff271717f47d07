"""From selected line-chains to a closed shape, and small gaps closed by a tolerance.

§3.3: "Any number of complete line-chains may be indicated ... These line-chains have their
end points joined together to form a closed shape."  Which end joins which the thesis does
not say; reconstructed: the chains are taken in the order named, each one turned so that
its nearer end meets the end reached so far, and the last end joins the first start.
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas.model import Drawing


class MissingChain(LookupError):
    """A chain number the frame does not have."""


def closed_shape(frame: Drawing, chains: tuple[int, ...]) -> np.ndarray:
    """The closed polygon (inches, (n, 2), first point repeated at the end)."""
    parts = []
    for c in chains:
        if not 1 <= c <= len(frame.chains):
            raise MissingChain(f"line-chain {c} is missing (the frame has "
                               f"{len(frame.chains)})")
        parts.append(frame.chains[c - 1].points)
    out = [parts[0]]
    for p in parts[1:]:
        end = out[-1][-1]
        if np.hypot(*(p[-1] - end)) < np.hypot(*(p[0] - end)):
            p = p[::-1]
        out.append(p)
    pts = np.concatenate(out)
    return np.concatenate([pts, pts[:1]])


def _seg_dist(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Distances from p to the segments a[i]-b[i] and the nearest points on them."""
    ab = b - a
    ll = np.einsum("ij,ij->i", ab, ab)
    t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.where(ll > 0, ll, 1), 0, 1)
    q = a + t[:, None] * ab
    return np.hypot(*(q - p).T), q


def gap_segments(frame: Drawing, tol: float) -> list[np.ndarray]:
    """Short segments closing each chain end that stops within ``tol`` inches of another
    chain (or of its own chain's other end): an animator's near miss (compare the gap
    closing of Toon Boom Harmony and OpenToonz).  Each segment is (2, 2) inches."""
    if tol <= 0:
        return []
    out = []
    chains = [c.points for c in frame.chains]
    for j, pts in enumerate(chains):
        if len(pts) < 2:
            continue
        for end, other in ((pts[0], pts[-1]), (pts[-1], pts[0])):
            best = np.hypot(*(other - end))
            target = other
            for k, q in enumerate(chains):
                if k == j or len(q) < 2:
                    continue
                d, near = _seg_dist(end, q[:-1], q[1:])
                i = int(np.argmin(d))
                if d[i] < best:
                    best, target = d[i], near[i]
            seg = np.array([end, target])
            # a chain's two ends near each other would give the same segment twice
            if 0 < best <= tol and not any(np.array_equal(seg[::-1], o) for o in out):
                out.append(seg)
    return out
