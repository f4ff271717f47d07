"""Plane use on the T5688 (thesis §3.3) and the lookup table that goes with it.

Planes 0-4 hold the fill colour (32 palette entries, 0 = unpainted), planes 5-6 the four
outline colours of the earlier KAS stages (0 = no outline), plane 7 the highlight.  The LUT
is arranged so that a set highlight bit shows the highlight colour whatever the other seven
planes hold, and an outline shows over any fill under it: index = h<<7 | outline<<5 | fill
(a fill in front of an outline clears it from the outline planes: ``occlusion``).
"""

from __future__ import annotations

from collections.abc import Sequence

FILL_MASK = 0x1F
OUTLINE_MASK = 0x60
OUTLINE_SHIFT = 5
HIGHLIGHT = 0x80
ALL_PLANES = 0xFF
MAX_FILL_COLOURS = 32
OUTLINE_SLOTS = 4  # slot 0 = no outline, 1-3 = the outline pens

RGB = tuple[int, int, int]


def lut(fills: Sequence[RGB], outlines: Sequence[RGB], highlight: RGB) -> list[RGB]:
    """The 256 24-bit LUT entries: highlight wins, then outline, then fill."""
    if len(fills) > MAX_FILL_COLOURS:
        raise ValueError(f"at most {MAX_FILL_COLOURS} fill colours, not {len(fills)}")
    out: list[RGB] = []
    for i in range(256):
        f, o = i & FILL_MASK, (i & OUTLINE_MASK) >> OUTLINE_SHIFT
        if i & HIGHLIGHT:
            out.append(tuple(highlight))
        elif o:
            out.append(tuple(outlines[o]))
        else:
            out.append(tuple(fills[f]) if f < len(fills) else tuple(fills[0]))
    return out


def fill_entries(fill: int) -> list[int]:
    """The LUT indices that show fill colour ``fill`` (no outline, no highlight): just one."""
    return [fill & FILL_MASK]
