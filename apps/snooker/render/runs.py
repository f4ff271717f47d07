"""Pixels sent to the Sigma as runs (thesis 6.4.1: the anti-aliased edge pixels and the
balls go as pixels, the polygons as outlines for the flood filler).

A row's contiguous pixels form one NGS polyline along the row: ``KI c GI x0y GJ x1y``, then
for each later colour ``KI c`` and the bare pair of the run's last pixel. A vector that
continues a polyline leaves out its first pixel (the end of the previous one), so each run
starts just after the last. Horizontal vectors are exact on any line drawer. The T5688
screen is the drawing area's bottom-left quadrant; device y points up.
"""

from __future__ import annotations

import numpy as np

from camlab88.protocols.sigma import Encoder


class RunWriter:
    """Turns (rows, xs, colour indices) into Sigma orders, remembering the drawing colour."""

    def __init__(self, enc: Encoder, height: int) -> None:
        self.enc = enc
        self.height = height
        self.colour = -1

    def set_colour(self, c: int) -> bytes:
        if c == self.colour:
            return b""
        self.colour = c
        return self.enc.colour8(c)

    def forget_colour(self) -> None:
        """After anything that may change the terminal's colour behind our back."""
        self.colour = -1

    def pixels(self, rows: np.ndarray, xs: np.ndarray, idx: np.ndarray) -> bytes:
        """Orders that set each (row, x) (row 0 = top of the screen) to its colour index."""
        if len(rows) == 0:
            return b""
        order = np.lexsort((xs, rows))
        r, x, c = rows[order], xs[order], idx[order].astype(np.int64)
        out = bytearray()
        start = 0
        n = len(r)
        breaks = np.nonzero((np.diff(r) != 0) | (np.diff(x) != 1))[0] + 1
        for end in [*breaks.tolist(), n]:
            out += self._segment(int(r[start]), x[start:end], c[start:end])
            start = end
        return bytes(out)

    def _segment(self, row: int, xs: np.ndarray, cs: np.ndarray) -> bytes:
        y = self.height - 1 - row
        change = np.nonzero(np.diff(cs))[0]
        ends = [*change.tolist(), len(cs) - 1]
        enc = self.enc
        out = bytearray(self.set_colour(int(cs[0])))
        out += enc.move(int(xs[0]), y) + enc.draw(int(xs[ends[0]]), y)
        for e in ends[1:]:
            out += self.set_colour(int(cs[e])) + enc.pair(int(xs[e]), y)
        return bytes(out)
