"""Figure 6.8 (§6.4, "taken from [Wilkes & Wiseman, 1982]") drawn on the T5688: a polygon
edge across a 4 x 4 pixel grid, the binary values a pixel gets from whether the polygon
covers its centre, and the grey values 0-15 the renderer's coverage anti-aliasing gives it,
each beside the image it makes (the cells are the pixels, magnified).

The greys are the renderer's own (``kernels.polygon``, the kernel every polygon of a frame
goes through), over the straight edge that fits the figure's numbers best
(tests/snooker_render/test_antialias.py): so the screen is the anti-aliasing at work, not
the figure's numbers copied. The layout, colours and captions are ours.
"""

from __future__ import annotations

import numpy as np

from camlab88.protocols.sigma import Encoder

EDGE = ((0.0, 4.2), (4.0, 1.0))  # figure units: pixel (col, row), row 0 at the top
CELL = 48                        # screen pixels a figure pixel
PANELS = (48, 288, 528)          # left x of each panel; each is 4 cells square
BOTTOM = 160                     # the panels' lower edge (device y points up)
TEXT, GRID, EDGE_COLOUR = 16, 17, 18
CAPTIONS = (("polygon edge", "across the pixel grid"), ("binary values", "(centre covered)"),
            ("grey values 0-15", "(area covered)"))


def edge_y(x: np.ndarray | float) -> np.ndarray | float:
    (x0, y0), (x1, y1) = EDGE
    return y0 + (y1 - y0) / (x1 - x0) * (np.asarray(x) - x0)


def grids() -> tuple[np.ndarray, np.ndarray]:
    """(binary, grey) 4 x 4, row 0 at the top: the polygon above the edge (white), sampled
    at pixel centres, and its coverage by the renderer's kernel in 16 levels."""
    from camlab88.apps.snooker.render import kernels as K

    verts = np.array([[-10.0, -10.0], [14.0, -10.0], [14.0, edge_y(14.0)],
                      [-10.0, edge_y(-10.0)]])
    img = np.zeros((4, 4, 1))
    K.polygon(img, verts, np.ones(1))
    centres = np.arange(4) + 0.5
    binary = (centres[:, None] < edge_y(centres[None, :])).astype(int)
    return binary, np.rint(img[..., 0] * 15).astype(int)


def _lut(enc: Encoder) -> bytes:
    out = bytearray()
    for g in range(16):  # grey level g of 15
        v = round(255 * g / 15)
        out += enc.lut24(g, v, v, v)
    for i, rgb in ((TEXT, (255, 170, 0)), (GRID, (70, 90, 200)), (EDGE_COLOUR, (255, 40, 40))):
        out += enc.lut24(i, *rgb)
    return bytes(out)


def setup(enc: Encoder) -> bytes:
    return enc.take_over() + enc.full_colour_screen() + _lut(enc) + enc.colour8(0) + enc.erase()


def _to_screen(x0: int, fx: float, fy: float) -> tuple[int, int]:
    return round(x0 + fx * CELL), round(BOTTOM + (4 - fy) * CELL)


def _grid(enc: Encoder, x0: int) -> bytes:
    out = bytearray(enc.colour8(GRID))
    for k in range(5):
        out += enc.move(*_to_screen(x0, k, 0)) + enc.draw(*_to_screen(x0, k, 4))
        out += enc.move(*_to_screen(x0, 0, k)) + enc.draw(*_to_screen(x0, 4, k))
    return bytes(out)


def _edge_panel(enc: Encoder, x0: int) -> bytes:
    """The white polygon at screen resolution (each screen row white up to the edge), the
    grid, and the edge itself."""
    out = bytearray(enc.colour8(15))
    for row in range(4 * CELL):
        fy = 4 - (row + 0.5) / CELL
        cut = min(4.0, (fy - EDGE[0][1]) / (EDGE[1][1] - EDGE[0][1]) * 4.0)
        if cut > 0:
            out += enc.move(x0, BOTTOM + row) + enc.block(round(x0 + cut * CELL) - 1,
                                                          BOTTOM + row)
    out += _grid(enc, x0) + enc.colour8(EDGE_COLOUR)
    (ax, ay), (bx, by) = EDGE
    t = (ay - 4.0) / (ay - by)  # the edge enters the grid at its bottom
    out += enc.move(*_to_screen(x0, ax + t * (bx - ax), 4.0)) + enc.draw(*_to_screen(x0, bx, by))
    return bytes(out)


def _value_panel(enc: Encoder, x0: int, values: np.ndarray, scale: int) -> bytes:
    """Each cell in its value's grey (``scale`` = the value shown white), the value written
    in it."""
    out = bytearray()
    for r in range(4):
        for c in range(4):
            grey = int(values[r, c]) * 15 // scale
            ax, ay = _to_screen(x0, c, r + 1)
            out += enc.colour8(grey) + enc.move(ax, ay) + enc.block(ax + CELL - 1, ay + CELL - 1)
            out += enc.colour8(TEXT) + enc.move(ax + CELL // 2 - 8, ay + CELL // 2 - 6)
            out += enc.text(f"{int(values[r, c]):2d}")
    return bytes(out + _grid(enc, x0))


def screen(enc: Encoder | None = None) -> bytes:
    """The whole figure as Sigma orders, from a reset terminal."""
    enc = enc or Encoder(high_res=True)
    binary, grey = grids()
    out = bytearray(setup(enc))
    out += enc.colour8(TEXT) + enc.move(48, 440)
    out += enc.text("Demonstration of anti-aliasing (after Wilkes & Wiseman, 1982)")
    out += _edge_panel(enc, PANELS[0]) + _value_panel(enc, PANELS[1], binary, 1)
    out += _value_panel(enc, PANELS[2], grey, 15)
    for x0, (a, b) in zip(PANELS, CAPTIONS, strict=True):
        out += enc.colour8(TEXT) + enc.move(x0, BOTTOM - 30) + enc.text(a)
        out += enc.move(x0, BOTTOM - 50) + enc.text(b)
    return bytes(out)
