"""The visualiser's pads (thesis §6.3.2): "A single virtual background pad is used; this
does not need to occupy physical graphics memory since it is all one colour.  Two pads are
used to hold double-buffered images of the billiard table while two more pads hold
double-buffered images of the balls.  The lookup tables are arranged such that the balls
appeared to be above the table, which is itself in front of the background".

All five pads sit in one clipping cluster at the same priority, so the Rainbow concatenates
their words: table values in planes 0-2, ball values in planes 3-6.  The LUT page maps a
word with a ball value to the ball's colour, else a table value to the table's colour, else
(0: both transparent) to the background's -- LUT[page * 256], the virtual pad's colour.
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.camera.projection import Camera
from camlab88.apps.snooker.table import Table
from camlab88.apps.snooker.visualiser import scene
from camlab88.protocols.rainbow.client import RainbowClient
from camlab88.protocols.rainbow.ui import DoubleBuffer

BACKGROUND = "#1a1e26"
TABLE_COLOURS = ("#000000", "#1f7a3a", "#2a9048", "#145a2a", "#7a4a24", "#52301a", "#202020",
                 "#000000")  # 0 unused (transparent), cloth, cushion top/face, rail top/side
BALL_COLOURS = ("#000000", "#f4f4f0", "#f0e020", "#10a040", "#8a5020", "#2050e0", "#f890b0",
                "#101010", "#d01818", *("#000000",) * 7)  # 0 transparent, cue..black, red
TABLE_PLANE, TABLE_DEPTH = 0, 3
BALL_PLANE, BALL_DEPTH = 3, 4


def page_colours() -> list[str]:
    out = []
    for word in range(256):
        t, b = word & 7, (word >> 3) & 15
        out.append(BALL_COLOURS[b] if b else TABLE_COLOURS[t] if t else BACKGROUND)
    return out


class ViewDisplay:
    """A perspective view of the table and balls, `width` x `height` at (x, y) in `parent`."""

    def __init__(self, client: RainbowClient, parent: int, x: int, y: int, width: int,
                 height: int, lut_page: int, priority: int = 1) -> None:
        c = self.client = client
        self.width, self.height = width, height
        c.set_lut(lut_page * 256, page_colours())
        self.cluster = c.create_cluster(width, height)
        c.map(parent, self.cluster, x, y, priority)
        self.background = c.create_pad(width, height, 0, plane=0, lut_page=lut_page)
        c.map(self.cluster, self.background, 0, 0, 1)
        self.tables = DoubleBuffer(c, self.cluster, width, height, TABLE_DEPTH, TABLE_PLANE,
                                   lut_page, priority=1)
        self.balls = DoubleBuffer(c, self.cluster, width, height, BALL_DEPTH, BALL_PLANE,
                                  lut_page, priority=1)
        self.shown: Camera | None = None
        self.table_redraws = 0

    def show(self, camera: Camera, table: Table, centres: np.ndarray,
             on_table: np.ndarray) -> None:
        """Draw into the back pads and swap; the table only if the view changed.  Both
        swaps take effect together at the next device frame."""
        c = self.client
        if self.shown is None or not camera.same_view(self.shown):
            img = scene.table_picture(camera, table, self.width, self.height)
            c.put_pixels(self.tables.back, 0, 0, img)
            self.tables.swap()
            self.shown = camera
            self.table_redraws += 1
        back = self.balls.back
        c.clear(back, 0)
        for cx, cy, r, value in scene.ball_discs(camera, centres, on_table, table.radius,
                                                 self.width, self.height):
            c.circle(back, cx, cy, r, value)
        self.balls.swap()

    def force_redraw(self) -> None:
        self.shown = None
