"""Where the editor's pads sit on the 768 x 576 screen, and the profile pad's scale.

The profile pad shows a half-section: the axis of revolution is its left edge (radius 0),
the floor its bottom edge (height 0); one cell unit is ``UNIT`` pixels, and points snap to
``SNAP`` of a unit so a drawn profile saves as short, exact-looking numbers.
"""

from __future__ import annotations

from camlab88.apps.actors.model import MAX_POINTS  # the file's limit on a lathe profile

STATUS = (16, 8, 736, 24)        # x, y, w, h: cell type, file, unsaved mark
PROFILE = (16, 40, 352, 448)
PREVIEW = (384, 40, 368, 296)
SLIDERS = (384, 344, 368, 144)
MESSAGE = (16, 496, 736, 36)
HELP = (16, 540, 736, 28)

UNIT = 320          # profile pad pixels per cell unit
AXIS_X = 16         # pad x of the axis (radius 0)
FLOOR_Y = 432       # pad y of the floor (height 0)
SNAP = 80           # points snap to 1/80 of a cell unit (4 pixels)
MAX_RADIUS = (PROFILE[2] - AXIS_X - 8) / UNIT
MAX_HEIGHT = (FLOOR_Y - 8) / UNIT
HIT = 6             # pixels: a press this near a point picks it up

# LUT pages (page * 256 + value)
PAGE_PROFILE, PAGE_SLIDERS, PAGE_MESSAGE, PAGE_STATUS, PAGE_PREVIEW, PAGE_HELP = 1, 2, 3, 4, 5, 6
PAGE_CHOICE, PAGE_MENU = 13, 15

__all__ = ["MAX_POINTS"]  # re-exported for the profile


def inside(rect: tuple[int, int, int, int], x: int, y: int) -> bool:
    rx, ry, rw, rh = rect
    return rx <= x < rx + rw and ry <= y < ry + rh
