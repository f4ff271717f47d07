"""Which parts of a frame's outlines a later fill hides (thesis §3.3: the order of shading
is defined "so there is no confusion as to which areas should appear to be 'in front of'
other areas").

A chain's outline stands at the depth of the last operation that uses it (a fill of a
shape it bounds, or a line operation). A fill in a colour other than 0 hides, inside its
filled pieces and on its boundary (which it covers in its colour), the outlines of every
chain whose depth is before it; its own chains' outlines and those of later operations
stay on top. A chain no operation uses is the cel's ink and always shows (reconstructed:
the thesis's painters worked on the back of the cel "to avoid obliterating the inked
outlines", §2). Colour 0 takes paint away, so it hides nothing; a region's face holds no
line by construction, so a region hides nothing either.

The host already rasterises each shape exactly as the terminal does (``seeds``, ``vector``),
so it knows each hidden pixel and sends only the visible pieces of an outline: no order
more, no plane more.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np

from camlab88.apps.kas.paint import seeds, vector
from camlab88.apps.kas.paint.autopaint import Step


class Cover:
    """One hiding fill: the pixels it paints over, worked out only when an outline that
    could be under it reaches its bounding box."""

    def __init__(self, depth: int, step: Step) -> None:
        self.depth, self._step = depth, step
        allp = np.concatenate(step.walls)
        self.box = (*allp.min(axis=0).tolist(), *allp.max(axis=0).tolist())

    def overlaps(self, px: np.ndarray) -> bool:
        x0, y0, x1, y1 = self.box
        lo, hi = px.min(axis=0), px.max(axis=0)
        return bool(lo[0] <= x1 and hi[0] >= x0 and lo[1] <= y1 and hi[1] >= y0)

    @cached_property
    def _mask(self) -> tuple[np.ndarray, tuple[int, int]]:
        f = seeds.faces(self._step.walls)
        filled = [f.label_at(x, y) for x, y in self._step.seeds]
        return (f.labels == 0) | np.isin(f.labels, [k for k in filled if k > 0]), f.origin

    def hides(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        mask, (ox, oy) = self._mask
        lx, ly = x - ox, y - oy
        h, w = mask.shape
        ok = (lx >= 0) & (lx < w) & (ly >= 0) & (ly < h)
        out = np.zeros(len(x), dtype=bool)
        out[ok] = mask[ly[ok], lx[ok]]
        return out


def depths(steps: list[Step]) -> dict[int, int]:
    """Chain number (1-based) -> index of the last step that uses it."""
    out: dict[int, int] = {}
    for i, s in enumerate(steps):
        if s.op.kind in ("fill", "line"):
            for c in s.op.chains:
                out[c] = i
    return out


def covers(steps: list[Step]) -> list[Cover]:
    """The fills that hide what is behind them."""
    return [Cover(i, s) for i, s in enumerate(steps)
            if s.op.kind == "fill" and s.colour != 0 and s.walls]


def visible_pieces(px: np.ndarray, hidden_by: list[Cover]) -> list[np.ndarray]:
    """The polyline ``px`` (area pixels) cut into the pieces no cover hides. A segment cut
    part way is sent from its first to its last visible pixel (the terminal's line between
    them is within a pixel of the original's)."""
    if not hidden_by:
        return [px]
    x, y, seg = vector.polyline_pixels(px)
    hidden = np.zeros(len(x), dtype=bool)
    for c in hidden_by:
        hidden |= c.hides(x, y)
    if not hidden.any():
        return [px]
    if len(px) == 1:
        return []
    pieces: list[list[tuple[int, int]]] = []
    cur: list[tuple[int, int]] = []
    for k in range(len(px) - 1):
        idx = np.flatnonzero(seg == k)
        vis = ~hidden[idx]
        a, b = tuple(int(v) for v in px[k]), tuple(int(v) for v in px[k + 1])
        ends = _runs(vis)
        if not ends or ends[0][0] != 0:
            cur = _flush(pieces, cur)
        for i0, i1 in ends:
            start = a if i0 == 0 else (int(x[idx[i0]]), int(y[idx[i0]]))
            end = b if i1 == len(idx) - 1 else (int(x[idx[i1]]), int(y[idx[i1]]))
            if i0 == 0 and cur:
                cur.append(end)
            else:
                cur = _flush(pieces, cur)
                cur = [start, end]
            if i1 != len(idx) - 1:
                cur = _flush(pieces, cur)
    _flush(pieces, cur)
    return [np.array(p, dtype=np.int64) for p in pieces]


def _runs(vis: np.ndarray) -> list[tuple[int, int]]:
    """(first, last) index of each run of True."""
    d = np.diff(np.concatenate([[0], vis.astype(np.int8), [0]]))
    return list(zip(np.flatnonzero(d == 1).tolist(), (np.flatnonzero(d == -1) - 1).tolist(),
                    strict=True))


def _flush(pieces: list[list[tuple[int, int]]], cur: list[tuple[int, int]]
           ) -> list[tuple[int, int]]:
    if cur:
        keep = [cur[0]] + [p for q, p in zip(cur, cur[1:], strict=False) if p != q]
        pieces.append(keep)
    return []
