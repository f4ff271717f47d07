"""The view onto the plane in screen pixels: zoom, pixel-accurate pan position, mapping.

The view is 752 x 576 pixels (the 768-pixel screen less the 16-pixel band the thesis keeps
for smooth panning, section 7.3.2). Positions are *world pixels* of the current zoom: cell
(cx, cy) covers world pixels [cx*z, cx*z+z) at zoom z; at the subpixel zoom one pixel covers
a ``side`` x ``side`` block of cells. World pixel coordinates are unbounded integers; cells
are taken modulo the 65536-cell plane, so panning goes round the torus smoothly.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from camlab88.apps.ca.engine import CENTRE, SIDE
from camlab88.apps.ca.session import MAX_CELLS_PER_PIXEL, subpixel_side  # noqa: F401 (re-exported)

SCREEN_W, SCREEN_H = 768, 576
BAND_W = 16
VIEW_W, VIEW_H = SCREEN_W - BAND_W, SCREEN_H
PIXEL_ZOOMS = (16, 8, 4, 2, 1)


@dataclass
class Viewport:
    zoom: int = 16  # pixels per cell; 0 = subpixel
    cells_per_pixel: int = 1  # subpixel only (an area: side * side)
    # world pixel at the view's left and top edges: whole cells, the plane's centre cell
    # in the middle of the 47 x 36 (section 7.3.1)
    px: int = (CENTRE - VIEW_W // 32) * 16
    py: int = (CENTRE - VIEW_H // 32) * 16
    grid: bool = True  # the optional grid at zoom 16 and 8

    @property
    def side(self) -> int:
        """Cells along one pixel's side at the subpixel zoom (1 otherwise)."""
        return math.isqrt(self.cells_per_pixel) if self.zoom == 0 else 1

    @property
    def name(self) -> str:
        return "subpixel" if self.zoom == 0 else str(self.zoom)

    @property
    def gaps(self) -> bool:
        """One-pixel separation between cells at zoom >= 4 (section 7.3.2)."""
        return self.zoom >= 4

    def cell_at(self, sx: int, sy: int) -> tuple[int, int]:
        """The cell under view pixel (sx, sy) (the top-left cell of a subpixel pixel)."""
        wx, wy = self.px + sx, self.py + sy
        if self.zoom == 0:
            return (wx * self.side) % SIDE, (wy * self.side) % SIDE
        return (wx // self.zoom) % SIDE, (wy // self.zoom) % SIDE

    def top_left_cell(self) -> tuple[int, int]:
        return self.cell_at(0, 0)

    def cells_across(self) -> tuple[int, int]:
        """How many cells the view spans (47 x 36 at zoom 16)."""
        if self.zoom == 0:
            return VIEW_W * self.side, VIEW_H * self.side
        return -(-VIEW_W // self.zoom), -(-VIEW_H // self.zoom)

    def centre_cell(self) -> tuple[int, int]:
        return self.cell_at(VIEW_W // 2, VIEW_H // 2)

    def world_of_cell(self, cx: int, cy: int) -> tuple[int, int]:
        """World pixel of cell (cx, cy)'s top-left, the representative nearest the view."""
        z = self.zoom or 1
        s = self.side
        plane = SIDE * z // s  # the plane's size in world pixels
        wx = (cx // s) * z
        wy = (cy // s) * z
        wx += ((self.px - wx + plane // 2) // plane) * plane
        wy += ((self.py - wy + plane // 2) // plane) * plane
        return wx, wy

    def screen_of_cell(self, cx: int, cy: int) -> tuple[int, int]:
        wx, wy = self.world_of_cell(cx, cy)
        return wx - self.px, wy - self.py

    def cell_visible(self, cx: int, cy: int) -> bool:
        sx, sy = self.screen_of_cell(cx, cy)
        z = self.zoom or 1
        return -z < sx < VIEW_W and -z < sy < VIEW_H

    def show_cell_at_centre(self, cx: int, cy: int) -> None:
        wx, wy = self.world_of_cell(cx, cy)
        z = self.zoom or 1
        self.px = wx + z // 2 - VIEW_W // 2
        self.py = wy + z // 2 - VIEW_H // 2

    def set_top_left(self, cx: int, cy: int) -> None:
        """Put cell (cx, cy) at the view's top-left corner (a logged view position)."""
        z = self.zoom or 1
        self.px = (cx // self.side) * z
        self.py = (cy // self.side) * z

    def set_zoom(self, zoom: int, cells_per_pixel: int = 1) -> None:
        """Change magnification keeping the cell at the centre of the view there."""
        if zoom != 0 and zoom not in PIXEL_ZOOMS:
            raise ValueError(f"zoom must be one of {PIXEL_ZOOMS} or 0 (subpixel)")
        if zoom == 0:
            subpixel_side(cells_per_pixel)
        centre = self.centre_cell()
        self.zoom = zoom
        self.cells_per_pixel = cells_per_pixel if zoom == 0 else 1
        self.show_cell_at_centre(*centre)

    def pan(self, dx: int, dy: int) -> None:
        """The mouse moved (dx, dy) with the left button held: the grid follows it."""
        self.px -= dx
        self.py -= dy
