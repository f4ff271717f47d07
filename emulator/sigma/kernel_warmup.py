"""Every Sigma raster kernel called once, with the argument types a terminal uses.

The completion of the "Sigma raster" kernel group (base.kernel_notice): after the first
cold compile of any of them, the rest compile too, so a later stream that needs another
(the T5688's abbreviated polylines and fills after a T5684's vectors) loads it from the
cache. A short stream through a real terminal rather than direct kernel calls, so the
argument types are the ones the terminal's own calls have.
"""

from __future__ import annotations

from camlab88.emulator.sigma.terminal import Terminal
from camlab88.protocols.sigma.encoder import Encoder


def warm_stream() -> bytes:
    """Vectors plain and dashed, NGS and AGS polylines, dots, a solid block, a fill."""
    e = Encoder()
    return b"".join((
        e.flag(), e.colour(1), e.move(10, 10), e.draw(60, 10),           # draw_line
        e.dash(0xF0F0), e.draw(60, 60), e.line_solid(),
        e.polyline([(10, 10), (30, 40), (50, 20)]),                        # draw_polyline
        e.abbreviated_polyline([(70, 70), (90, 80), (120, 70)]),           # AGS scan_points
        e.move(5, 100), e.dots([1, 2, 3]),                                 # dot_run
        e.move(200, 200), e.block(220, 220),                               # fill_rect
        e.move(300, 300), e.fill(1),                                       # boundary_fill
    ))


def compile_kernels() -> None:
    Terminal("t5684").feed(warm_stream())
