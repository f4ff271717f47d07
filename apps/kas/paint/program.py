"""The painting program on the Sigma T5688 (thesis §3.3), in Sigma orders only.

``PaintProgram`` makes the bytes; ``Line`` writes them to the port of a T5688 on the
9600-baud serial line (virtual clock) and waits for them, so every figure of line time is
what a 1984 animator would have waited.  Whoever runs the machine hands the link over
(protocols.link.port.BatchLink).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from camlab88.apps.kas.model import AnimSequence
from camlab88.apps.kas.paint import areas, mixing, orders, outlines, planes
from camlab88.apps.kas.paint.autopaint import AutoPainter, FramePlan
from camlab88.apps.kas.paint.ops import OpsFile
from camlab88.protocols.link.port import BatchLink
from camlab88.protocols.sigma import Encoder

HIGHLIGHT_RGB = (255, 0, 255)  # reconstructed: any colour unlike the pens; magenta


class Line:
    """The host's end of the line (no XON/XOFF: the orders are binary).  ``send`` returns
    the line time when the last byte has arrived; the terminal has taken every byte by then
    (the link waits for the line)."""

    def __init__(self, link: BatchLink) -> None:
        self.link = link
        self.chars = 0

    def send(self, data: bytes) -> float:
        end = self.link.port.write(data)
        self.chars += len(data)
        self.link.wait()
        return end

    @property
    def now(self) -> float:
        return self.link.port.now


@dataclass
class PaintProgram:
    seq: AnimSequence
    ops: OpsFile
    enc: Encoder = field(default_factory=lambda: Encoder(high_res=True))

    def __post_init__(self) -> None:
        self.outline = outlines.plan(self.seq)
        self.painter = AutoPainter(self.seq, self.ops)
        self.current = 1

    # ------------------------------------------------------------ the terminal's state
    def lut(self) -> list[planes.RGB]:
        return planes.lut(self.ops.palette.entries, self.outline.rgb, HIGHLIGHT_RGB)

    def setup(self) -> bytes:
        """Graphics mode, reset, 4-digit coordinates, all planes, the arranged LUT."""
        e = self.enc
        out = bytearray(e.take_over() + e.coords4())
        out += e.sequence_length(0) + e.graphics_on() + e.alpha_off() + e.cursor_off()
        out += e.write_mask(planes.ALL_PLANES) + e.display_mask(planes.ALL_PLANES)
        out += b"".join(e.lut24(i, *rgb) for i, rgb in enumerate(self.lut()))
        return bytes(out + e.erase() + e.line_solid())

    def palette_entry(self, i: int) -> bytes:
        """One edited palette entry: its one LUT entry (the swatch, the painting and the
        preview all change at once; nothing is redrawn)."""
        return b"".join(self.enc.lut24(k, *self.ops.palette[i]) for k in planes.fill_entries(i))

    def show(self, view: int) -> bytes:
        """KQ: a working area full-screen (areas.*.view), or 4 for the quarter-size preview."""
        return self.enc.view(view)

    # ------------------------------------------------------------ painting
    def plan(self, n: int) -> FramePlan:
        return self.painter.plan(n)

    def frame(self, n: int, area: areas.Area = areas.PAINTING) -> tuple[bytes, FramePlan]:
        """Frame ``n`` (1-based) painted into ``area`` from the operations."""
        p = self.plan(n)
        runs = outlines.runs(self.seq.frames[n - 1], self.outline)
        return orders.frame_bytes(self.enc, p, runs, area.box()), p

    def select(self, n: int, chains: tuple[int, ...]) -> bytes:
        """Highlight chains: 1s into the highlight plane only (write mask 0x80, §3.3)."""
        e, origin = self.enc, areas.PAINTING.origin
        out = bytearray(e.write_mask(planes.HIGHLIGHT) + e.colour8(planes.HIGHLIGHT))
        for c in chains:
            px = areas.dedup(areas.to_px(self.seq.frames[n - 1].chains[c - 1].points))
            out += orders.poly(e, px, origin)
        return bytes(out + e.write_mask(planes.ALL_PLANES))

    def clear_selection(self) -> bytes:
        return orders.clear_highlight(self.enc) + self.enc.write_mask(planes.ALL_PLANES)

    def mixing_area(self) -> bytes:
        return mixing.area(self.enc, self.ops.palette, self.current, self._text_slot())

    def editor(self) -> bytes:
        """The RGB editor redrawn for the current entry."""
        return mixing.editor(self.enc, self.ops.palette, self.current, self._text_slot())

    def _text_slot(self) -> int:
        """The brightest outline colour, for the editor's bars and figures."""
        return max(range(1, 4), key=lambda s: (sum(self.outline.rgb[s]), -s))


def nearest_chain(seq: AnimSequence, n: int, point: tuple[float, float]) -> int:
    """The 1-based number of the chain nearest ``point`` (inches) in frame ``n``: what
    *select* picks when the cursor is put near a chain."""
    best, which = np.inf, 0
    for j, c in enumerate(seq.frames[n - 1].chains):
        d = float(np.min(np.hypot(*(c.points - np.asarray(point)).T))) if len(c) else np.inf
        if d < best:
            best, which = d, j + 1
    if not which:
        raise ValueError(f"frame {n} has no line-chains")
    return which
