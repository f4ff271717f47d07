"""The four outline colours (thesis §3.3: "two of the remaining three planes were used to
hold the (four colour) outlines produced by earlier stages of KAS"): slot 0 is no outline,
slots 1-3 the three pens the sequence uses most, other pens the nearest of those (as the
line test's two-plane buffers do, §3.1.4).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from camlab88.apps.kas.model import PALETTE, AnimSequence, Drawing
from camlab88.apps.kas.paint import areas
from camlab88.apps.kas.paint.planes import RGB
from camlab88.apps.kas.pens import pen_slots


@dataclass(frozen=True)
class OutlinePlan:
    slot_of_pen: dict[int, int]
    rgb: tuple[RGB, RGB, RGB, RGB]  # slot 0 (unused: no outline) .. 3

    def slot(self, pen: int) -> int:
        return self.slot_of_pen.get(pen, 1)


def _palette_rgb(pen: int) -> tuple[int, int, int]:
    return PALETTE.get(pen, ("", (255, 255, 255)))[1]


def plan(seq: AnimSequence) -> OutlinePlan:
    top, slots = pen_slots(seq, _palette_rgb)
    rgb = [(0, 0, 0)] + [tuple(int(v) for v in _palette_rgb(p)) for p in top]
    while len(rgb) < 4:
        rgb.append(rgb[-1])
    return OutlinePlan(slots, tuple(rgb))


class Run(NamedTuple):
    """One outline polyline: its slot, its area pixels, the 1-based chain it is part of."""

    slot: int
    px: np.ndarray
    chain: int


def runs(frame: Drawing, outline: OutlinePlan) -> list[Run]:
    """(slot, area pixels, chain) polylines: each chain cut where its segments change slot
    (a point's colour is that of the segment drawn to it, §3.1.1)."""
    out = []
    for j, c in enumerate(frame.chains, start=1):
        px = areas.to_px(c.points)
        slots = np.array([outline.slot(int(p)) for p in c.colours])
        if len(px) == 1:
            out.append(Run(int(slots[0]), px, j))
            continue
        seg = slots[1:]
        cut = np.flatnonzero(np.diff(seg)) + 1
        for a, b in zip(np.r_[0, cut], np.r_[cut, len(seg)], strict=True):
            out.append(Run(int(seg[a]), areas.dedup(px[a:b + 1]), j))
    return out
