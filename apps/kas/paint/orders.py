"""Frame plans as Sigma T5688 orders (thesis §3.3).

Per frame, into one working area: the area cleared (a solid block of 0 on all planes); each
step in front-to-back order: walls drawn on all planes in 0x80 (so they are the only pixels
of that value), the firmware filler (``KK80``) started at every seed, stopping at them,
writing the fill colour into the five fill planes and clearing the outline planes under it
(a fill is in front of every outline drawn before it, ``occlusion``); the cover drawn in the
fill colour; then the outlines into their two planes, less the pieces a later fill hides,
chains coloured by ``line`` operations taken out of the outline planes, and the highlight
plane cleared (``KW80 DA``).
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas.paint import occlusion
from camlab88.apps.kas.paint.autopaint import FramePlan, Step
from camlab88.apps.kas.paint.outlines import Run
from camlab88.apps.kas.paint.planes import (
    ALL_PLANES,
    FILL_MASK,
    HIGHLIGHT,
    OUTLINE_MASK,
    OUTLINE_SHIFT,
)
from camlab88.protocols.sigma import Encoder


def poly(enc: Encoder, px: np.ndarray, origin: tuple[int, int]) -> bytes:
    """A polyline in abbreviated mode (about half the characters, §3.1.4)."""
    key = (id(px), origin, enc.high_res)
    hit = _POLY_MEMO.get(key)
    if hit is not None and hit[0] is px:
        return hit[1]
    pts = (px + np.asarray(origin)).tolist()
    if len(pts) == 1:
        pts = pts * 2  # a dot: a vector of length 0
    data = enc.abbreviated_polyline(pts)
    if len(_POLY_MEMO) > 4096:
        _POLY_MEMO.clear()
    _POLY_MEMO[key] = (px, data)  # the array is held, so its id is not reused meanwhile
    return data


# One frame's walls are sent again by every region step; the bytes depend only on the
# points, the area and the encoder's high-resolution flag.
_POLY_MEMO: dict[tuple[int, tuple[int, int], bool], tuple[np.ndarray, bytes]] = {}


def clear_area(enc: Encoder, box: tuple[int, int, int, int]) -> bytes:
    x0, y0, x1, y1 = box
    return (enc.write_mask(ALL_PLANES) + enc.colour8(0) + enc.move(x0, y0)
            + enc.block(x1, y1, solid=True))


def clear_highlight(enc: Encoder) -> bytes:
    """Clearing the highlight plane removes every highlight; nothing is redrawn (§3.3)."""
    return enc.write_mask(HIGHLIGHT) + enc.erase()


def step_bytes(enc: Encoder, s: Step, origin: tuple[int, int]) -> bytes:
    out = bytearray()
    if s.walls:
        out += enc.write_mask(ALL_PLANES) + enc.colour8(HIGHLIGHT)
        for w in s.walls:
            out += poly(enc, w, origin)
        # a fill in a colour hides the outlines under it (their planes cleared as it spreads)
        hides = s.op.kind == "fill" and s.colour != 0
        out += enc.write_mask(FILL_MASK | OUTLINE_MASK if hides else FILL_MASK)
        out += enc.colour8(s.colour)
        for x, y in s.seeds:
            out += enc.move(x + origin[0], y + origin[1]) + enc.fill8(HIGHLIGHT)
    if s.cover:
        out += enc.write_mask(FILL_MASK) + enc.colour8(s.colour)
        for c in s.cover:
            out += poly(enc, c, origin)
    if s.clear:
        out += clear_highlight(enc)
    return bytes(out)


def outline_bytes(enc: Encoder, runs: list[Run], steps: list[Step],
                  origin: tuple[int, int]) -> bytes:
    """The outlines in front-to-back order's sense: each less what a later fill hides."""
    out = bytearray(enc.write_mask(OUTLINE_MASK))
    last = -1
    depth, covers = occlusion.depths(steps), occlusion.covers(steps)
    for slot, px, chain in runs:
        d = depth.get(chain)
        hidden_by = [] if d is None else [c for c in covers if c.depth > d and c.overlaps(px)]
        for piece in occlusion.visible_pieces(px, hidden_by):
            if slot != last:
                out += enc.colour8(slot << OUTLINE_SHIFT)
                last = slot
            out += poly(enc, piece, origin)
    unline = [u for s in steps for u in s.unline]
    if unline:
        out += enc.colour8(0)
        for u in unline:
            out += poly(enc, u, origin)
    return bytes(out)


def frame_bytes(enc: Encoder, plan: FramePlan, runs: list[Run],
                box: tuple[int, int, int, int]) -> bytes:
    """One whole painted frame into the area ``box``."""
    origin = (box[0], box[1])
    out = bytearray(clear_area(enc, box))
    for s in plan.steps:
        out += step_bytes(enc, s, origin)
    out += outline_bytes(enc, runs, plan.steps, origin)
    return bytes(out + clear_highlight(enc) + enc.write_mask(ALL_PLANES))
