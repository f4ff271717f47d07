"""The editor's pads: the profile (a half-section with the axis at its left edge and a
cursor cross), the turning preview (an 8-bit pad on its own LUT page, reloaded each time a
new picture is uploaded), the status line, the message pad and the key help."""

from __future__ import annotations

import numpy as np

from camlab88.apps.actors.editor import layout as L
from camlab88.apps.actors.editor.profile import Point, to_pixels
from camlab88.apps.actors.editor.quantise import quantise
from camlab88.apps.actors.editor.sliders import SliderPad
from camlab88.protocols.rainbow.client import SCREEN, RainbowClient
from camlab88.protocols.rainbow.ui import MessageArea

BG, GRID, AXIS, LINE, POINT, PICKED, LABEL = range(7)
PROFILE_COLOURS = ["#101828", "#27324a", "#8090b0", "#f8c890", "#ffffff", "#ff6060",
                   "#a0a8c0"]
CURSOR_BIT = 128  # the cursor pad (plane 7) over the profile pad (planes 0-3)
CURSOR = 11
HELP_TEXT = ("left: add / drag a point, set a slider   right: delete a point   middle: menu\n"
             "s save   Tab next cell type   Del delete point   q or Esc quit (y/n/Esc)")


class Display:
    def __init__(self, client: RainbowClient) -> None:
        c = self.client = client
        c.set_lut(0, ["#181c24"])  # the screen between the pads
        self._profile_pads()
        x, y, w, h = L.PREVIEW
        self.preview = c.create_pad(w, h, 8, 0, L.PAGE_PREVIEW)
        c.map(SCREEN, self.preview, x, y, 5)
        self.sliders = SliderPad(c, L.SLIDERS, L.PAGE_SLIDERS)
        self.status = MessageArea(c, *L.STATUS, lut_page=L.PAGE_STATUS)
        self.message = MessageArea(c, *L.MESSAGE, lut_page=L.PAGE_MESSAGE)
        self.help = MessageArea(c, *L.HELP, lut_page=L.PAGE_HELP)
        self.help.show(HELP_TEXT, "#c8e8ff")

    def _profile_pads(self) -> None:
        c = self.client
        x, y, w, h = L.PROFILE
        base = L.PAGE_PROFILE * 256
        c.set_lut(base, PROFILE_COLOURS)
        c.set_lut(base + CURSOR_BIT, ["#ffff80"] * 16)
        cluster = c.create_cluster(w, h)  # clips the cursor to the profile
        c.map(SCREEN, cluster, x, y, 5)
        self.profile = c.create_pad(w, h, 4, 0, L.PAGE_PROFILE)
        c.map(cluster, self.profile, 0, 0, 1)
        self.cursor = c.create_pad(CURSOR, CURSOR, 1, 7, L.PAGE_PROFILE)
        half = CURSOR // 2
        c.line(self.cursor, 0, half, CURSOR - 1, half, 1)
        c.line(self.cursor, half, 0, half, CURSOR - 1, 1)
        self.cursor_arc = c.map(cluster, self.cursor, -CURSOR, -CURSOR, 1)

    def move_cursor(self, mx: int, my: int) -> None:
        """The cross at screen (mx, my) (clipped away outside the profile pad)."""
        self.client.move(self.cursor_arc, mx - L.PROFILE[0] - CURSOR // 2,
                         my - L.PROFILE[1] - CURSOR // 2)

    def draw_profile(self, points: list[Point], picked: int | None) -> None:
        c, pad = self.client, self.profile
        _x, _y, w, _h = L.PROFILE
        c.clear(pad, BG)
        step = L.UNIT // 8  # grid every 1/8 of a cell unit
        for gx in range(L.AXIS_X, w, step):
            c.line(pad, gx, 0, gx, L.FLOOR_Y, GRID)
        for gy in range(L.FLOOR_Y, -1, -step):
            c.line(pad, L.AXIS_X, gy, w - 1, gy, GRID)
        c.line(pad, L.AXIS_X, 0, L.AXIS_X, L.FLOOR_Y, AXIS)
        c.line(pad, 0, L.FLOOR_Y, w - 1, L.FLOOR_Y, AXIS)
        c.text(pad, L.AXIS_X + 4, L.FLOOR_Y + 4, "radius ->   (grid: 1/8 cell)", LABEL)
        c.text(pad, L.AXIS_X + 4, 4, "height", LABEL)
        pix = [to_pixels(p) for p in points]
        for (x0, y0), (x1, y1) in zip(pix, pix[1:], strict=False):
            c.line(pad, x0, y0, x1, y1, LINE)
        for i, (px, py) in enumerate(pix):
            c.rect(pad, px - 2, py - 2, 5, 5, PICKED if i == picked else POINT)

    def show_preview(self, rgb: np.ndarray) -> None:
        values, palette = quantise(rgb)
        self.client.set_lut(L.PAGE_PREVIEW * 256, [tuple(int(v) for v in p) for p in palette])
        self.client.put_pixels(self.preview, 0, 0, values)
