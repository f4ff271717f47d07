"""The colour-mixing area (figure 3.7, top right): the palette as swatches and the RGB
editor, which "displays the current proportion of red, green and blue in the colour and
allows these values to be incrementally altered" (thesis §3.3).

Swatches are drawn in the fill planes, so they show each entry through the LUT and change
the instant an entry is edited, in the painting area too; the current entry is framed in
the highlight plane; the editor's bars and figures are drawn in the outline planes (slot 1).
Layout reconstructed (the figure is not reproduced in the text).
"""

from __future__ import annotations

from camlab88.apps.kas.paint.areas import MIXING
from camlab88.apps.kas.paint.palette import Palette
from camlab88.apps.kas.paint.planes import (
    ALL_PLANES,
    FILL_MASK,
    HIGHLIGHT,
    OUTLINE_MASK,
    OUTLINE_SHIFT,
)
from camlab88.protocols.sigma import Encoder

SW, SH, GAP = 80, 60, 12        # swatch size and spacing, pixels
COLS = 8
BAR_X, BAR_Y, BAR_W, BAR_H, BAR_GAP = 140, 40, 512, 24, 12


def _origin() -> tuple[int, int]:
    return MIXING.origin


def swatch_box(i: int) -> tuple[int, int, int, int]:
    """Area pixels of palette entry ``i``'s swatch: rows from the top, 8 to a row."""
    x0, y0 = _origin()
    r, c = divmod(i, COLS)
    x = x0 + GAP + c * (SW + GAP)
    top = y0 + 512 - GAP - r * (SH + GAP)
    return x, top - SH, x + SW - 1, top - 1


def _block(enc: Encoder, box: tuple[int, int, int, int]) -> bytes:
    return enc.move(box[0], box[1]) + enc.block(box[2], box[3], solid=True)


def swatches(enc: Encoder, palette: Palette) -> bytes:
    out = bytearray(enc.write_mask(FILL_MASK))
    for i in range(len(palette)):
        out += enc.colour8(i) + _block(enc, swatch_box(i))
    return bytes(out)


def frame_current(enc: Encoder, current: int, previous: int | None = None) -> bytes:
    """The current entry framed in the highlight plane (only that plane is written)."""
    out = bytearray(enc.write_mask(HIGHLIGHT))
    for i, colour in ((previous, 0), (current, HIGHLIGHT)):
        if i is None:
            continue
        x0, y0, x1, y1 = swatch_box(i)
        out += enc.colour8(colour) + enc.move(x0 - 3, y0 - 3) + enc.block(x1 + 3, y1 + 3,
                                                                           solid=False)
    return bytes(out)


def editor(enc: Encoder, palette: Palette, current: int, slot: int = 1) -> bytes:
    """The RGB editor: one bar per gun, as long as its proportion, and the values, drawn
    in outline colour ``slot``."""
    x0, y0 = _origin()
    top = y0 + BAR_Y + 3 * (BAR_H + BAR_GAP) + 14  # above the label's glyphs
    out = bytearray(enc.write_mask(ALL_PLANES) + enc.colour8(0))
    out += _block(enc, (x0 + 8, y0 + BAR_Y - 4, x0 + 767, top))
    out += enc.write_mask(OUTLINE_MASK) + enc.colour8(slot << OUTLINE_SHIFT)
    for g, (name, value) in enumerate(zip("BGR", palette[current][::-1], strict=True)):
        y = y0 + BAR_Y + g * (BAR_H + BAR_GAP)
        out += enc.move(x0 + 16, y + 6) + enc.text(f"{name} {value:3d}")
        out += enc.move(x0 + BAR_X, y) + enc.block(x0 + BAR_X + BAR_W, y + BAR_H, solid=False)
        if value:
            length = round(BAR_W * value / 255)
            out += _block(enc, (x0 + BAR_X, y, x0 + BAR_X + length, y + BAR_H))
    out += enc.move(x0 + 16, y0 + BAR_Y + 3 * (BAR_H + BAR_GAP)) + enc.text(f"COLOUR {current}")
    return bytes(out)


def area(enc: Encoder, palette: Palette, current: int, slot: int = 1) -> bytes:
    x0, y0, x1, y1 = MIXING.box()
    out = enc.write_mask(ALL_PLANES) + enc.colour8(0) + _block(enc, (x0, y0, x1, y1))
    return (out + swatches(enc, palette) + frame_current(enc, current)
            + editor(enc, palette, current, slot))
