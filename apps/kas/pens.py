"""Which pens share the few colours a small display has: the most used pens keep their own
colour, every other pen borrows the nearest of theirs (the line test's four colours, the
painting program's outline slots)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from camlab88.apps.kas.model import AnimSequence


def pen_counts(seq: AnimSequence) -> dict[int, int]:
    """Points drawn with each pen over the whole sequence."""
    counts: dict[int, int] = {}
    for f in seq.frames:
        for c in f.chains:
            for pen, n in zip(*np.unique(c.colours, return_counts=True), strict=True):
                counts[int(pen)] = counts.get(int(pen), 0) + int(n)
    return counts


def pen_slots(seq: AnimSequence, rgb: Callable[[int], Sequence[int]],
              n: int = 3) -> tuple[list[int], dict[int, int]]:
    """The ``n`` most used pens (by points, ties to the lower pen; pen 1 in an empty
    sequence) in slots 1..n, and every other pen in the slot of the nearest of them by
    ``rgb`` (sum of absolute differences, ties to the lower slot)."""
    counts = pen_counts(seq)
    top = sorted(counts, key=lambda p: (-counts[p], p))[:n] or [1]
    slots = {p: i + 1 for i, p in enumerate(top)}
    for p in counts:
        if p not in slots:
            own = np.array(rgb(p))
            slots[p] = 1 + int(np.argmin([np.abs(own - np.array(rgb(q))).sum() for q in top]))
    return top, slots
