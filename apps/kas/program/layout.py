"""Where things are on the Sigma T5684's 768 x 512 screen (device pixels, y up), and the LUT.

The editor screen of §3.1.1 / figure 3.1: the twelve-field rectangle at 48 pixels to the inch
(576 x 420) in the lower left, the menu row of coloured boxes above it, the prompt and status
lines at the top, the list of keyboard commands to the right.  The tablet covers the whole
screen (16" x 10.67" at the same scale), so the menu is "at the top of the tablet" (§3.1.1).
"""

from __future__ import annotations

from camlab88.apps.kas.model import FIELD_H, FIELD_W, PALETTE
from camlab88.protocols.tablets.input_layer import WorkingArea

SCREEN_W, SCREEN_H = 768, 512
SCALE = 48.0                      # pixels per inch of the twelve-field
FIELD_X0, FIELD_Y0 = 8, 8         # bottom-left pixel of the twelve-field
FIELD_X1 = FIELD_X0 + round(FIELD_W * SCALE)   # 584
FIELD_Y1 = FIELD_Y0 + round(FIELD_H * SCALE)   # 428
CENTRE_X = (FIELD_X0 + FIELD_X1) / 2           # 296
CENTRE_Y = (FIELD_Y0 + FIELD_Y1) / 2           # 218
PANEL_X = FIELD_X1 + 12           # the keyboard-command list
STATUS_Y = 476                    # mode, pen, section, zoom
MESSAGE_Y = 496                   # prompts and messages
CHAR_W, CHAR_H = 8, 10            # graphics text cell (emulator font: 5 x 9 glyph in 8 wide)

# The tablet's working area: the whole screen, in inches, (0, 0) top left, y down.
TABLET_AREA = WorkingArea(SCREEN_W / SCALE, SCREEN_H / SCALE, "inch", "kas-screen")

# LUT plan (16 entries, 4 planes).  0 background; 1-8 the pens; then the editor's own colours.
BG, MARKS, OLD, DIM, GUIDE, GUIDE_NEXT, TEXT, HILITE = 0, 9, 10, 11, 12, 13, 14, 15
CYAN_PEN, MAGENTA_PEN = 6, 7  # the editing cursors use the cyan and magenta paint pots
# Edit mode's dim versions of the pens (§3.1.1 "a dim version of the line's colour"): the
# guide entries are free in edit mode (the guide keyframe shows in drawing mode only), so
# 11, 12 and 13 are reloaded with dim pens while the background is shown (docs/fidelity/kas.md)
DIM_ENTRIES = (DIM, GUIDE, GUIDE_NEXT)
DIM_SHARE = 0.45  # a dim pen is 45 % of the way from the background to the pen


def field_to_px(x: float, y: float) -> tuple[float, float]:
    """Screen field inches (centre origin, y up) -> device pixels (y up)."""
    return CENTRE_X + x * SCALE, CENTRE_Y + y * SCALE


def px_to_field(px: float, py: float) -> tuple[float, float]:
    return (px - CENTRE_X) / SCALE, (py - CENTRE_Y) / SCALE


def tablet_to_field(x: float, y: float) -> tuple[float, float]:
    """Input-layer coordinates (TABLET_AREA inches, top left, y down) -> field inches."""
    return px_to_field(x * SCALE, SCREEN_H - y * SCALE)


def field_to_mouse(x: float, y: float) -> tuple[float, float]:
    """Field inches -> a window mouse position (pixels, row 0 = top) on the 768 x 512 view."""
    px, py = field_to_px(x, y)
    return px, SCREEN_H - py


def _nib(v: int) -> int:
    return max(0, min(15, round(v / 17)))


def lut_plan(background: str = "black") -> list[tuple[int, int, int]]:
    """The editor's 16 LUT entries as 4-bit (r, g, b)."""
    if background not in ("black", "white"):
        raise ValueError(f"background is black or white, not {background!r}")
    white = background == "white"
    lut = [(15, 15, 15) if white else (0, 0, 0)]
    for pen in range(1, 9):
        rgb = PALETTE[pen][1]
        if white and pen == 1:
            rgb = (0, 0, 0)  # the white pen draws in black on white, as on paper
        lut.append(tuple(_nib(c) for c in rgb))
    lut += [
        (7, 7, 7),                                   # 9 field marks, menu boxes
        (9, 5, 12) if white else (6, 2, 8),          # 10 old positions: faint purple
        (11, 11, 11) if white else (5, 5, 5),        # 11 unmoved chains: dim
        (8, 10, 15) if white else (3, 4, 9),         # 12 previous keyframe (guide)
        (15, 8, 0) if white else (15, 15, 8),        # 13 its chain to draw next
        (0, 0, 0) if white else (12, 15, 12),        # 14 text
        (15, 0, 0) if white else (15, 15, 15),       # 15 highlight frames
    ]
    return lut


def dim_rgb(rgb: tuple[int, int, int], background: str = "black") -> tuple[int, int, int]:
    """A pen's 4-bit colour dimmed: moved DIM_SHARE of the way from the background to it."""
    bg = 15 if background == "white" else 0
    return tuple(round(bg + (c - bg) * DIM_SHARE) for c in rgb)


def dim_lut(lut: list[tuple[int, int, int]], pens: dict[int, int],
            background: str = "black") -> list[tuple[int, int, int]]:
    """``lut`` with each dim entry of ``pens`` (pen -> entry) loaded with that pen dimmed."""
    out = list(lut)
    for pen, entry in pens.items():
        if entry in DIM_ENTRIES:
            out[entry] = dim_rgb(lut[pen], background)
    return out
