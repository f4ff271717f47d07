"""The program's pads (§6.2.1): the table in one pad, the balls in two double-buffered pads
with transparent backgrounds, a small cyan cursor in a third, and the message areas.

Transparency is done in the lookup table: the table pad (3 bits, planes 0-2), the ball
pads (4 bits, planes 3-6) and the cursor pad (1 bit, plane 7) are mapped at the same
priority, so where they overlap the Rainbow concatenates their words; LUT page 1 is filled
so that a ball value of 0 shows the table beneath and a cursor value of 0 shows whatever is
under the cursor.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from camlab88.apps.snooker.program import layout
from camlab88.apps.snooker.program.layout import TableView
from camlab88.apps.snooker.table import BROWN, N_BALLS, is_red
from camlab88.base.plainstate import Blob, Int, ListOf, Opt, Record, Str, Tuple
from camlab88.protocols.rainbow.client import SCREEN, SCREEN_H, SCREEN_W, RainbowClient
from camlab88.protocols.rainbow.ui import DoubleBuffer, MessageArea

PAGE = 1
# table pad values
BACKGROUND, CLOTH, CUSHION, WOOD, POCKET, MARKING = 0, 1, 2, 3, 4, 5
TABLE_COLOURS = ["#1c2030", "#1f7a3a", "#14592a", "#6b3f1f", "#050505", "#e8f0e8",
                 "#000000", "#000000"]
# ball pad values: 1..7 the cue ball and colours, 8 red, then the overlays
RED = 8
MAGENTA, SPIN, MOVING, DOTS, SELECT = 9, 10, 11, 12, 13
BALL_COLOURS = {
    1: "#f4f4f0", 2: "#f0e020", 3: "#10a040", 4: "#8a5020", 5: "#2050e0", 6: "#f890b0",
    7: "#101010", RED: "#d01818", MAGENTA: "#ff30ff", SPIN: "#60f0ff", MOVING: "#ffb040",
    DOTS: "#ffffff", SELECT: "#00ffff", 14: "#000000", 15: "#000000",
}
CURSOR_COLOUR = "#00ffff"
CURSOR_SIZE = 15
PRIORITY = 1


def ball_value(ball: int) -> int:
    return RED if is_red(ball) else ball + 1


def page_colours() -> list[str]:
    """LUT page 1: word = table | ball << 3 | cursor << 7."""
    out = []
    for word in range(256):
        t, b, c = word & 7, (word >> 3) & 15, word >> 7
        out.append(CURSOR_COLOUR if c else BALL_COLOURS[b] if b else TABLE_COLOURS[t])
    return out


@dataclass
class Overlay:
    """What is drawn over the balls this frame: lines and dots, each with a pad value."""

    lines: list[tuple[int, int, int, int, int]] = field(default_factory=list)
    dots: list[tuple[int, int, int]] = field(default_factory=list)
    rings: list[tuple[int, int, int, int]] = field(default_factory=list)  # cx, cy, r, value


class TextBox:
    """A message area that redraws only when its text or colour changes."""

    def __init__(self, client: RainbowClient, box: tuple[int, int, int, int], page: int) -> None:
        self.area = MessageArea(client, *box, lut_page=page, priority=10)
        self.shown: tuple[str, str] | None = None

    def show(self, text: str, colour: str) -> None:
        if self.shown != (text, colour):
            self.area.show(text, colour)
            self.shown = (text, colour)

    def hide(self) -> None:
        if self.shown is not None:
            self.area.hide()
            self.shown = None


def _ints(rows: tuple[tuple[int, ...], ...]) -> list[tuple[int, ...]]:
    return [tuple(int(v) for v in row) for row in rows]


SHOWN = Opt(Tuple((Str(65536), Str(64))))  # a text box's (text, colour), or hidden
SCENE = Opt(Record(pos=Blob(4096), on=Blob(4096), lines=ListOf(Tuple((Int(),) * 5)),
                   dots=ListOf(Tuple((Int(),) * 3)), rings=ListOf(Tuple((Int(),) * 4))))
BOXES = ("help", "info", "step_box", "status", "frame_box")


class Display:
    # its declared state: the balls' buffers, the cursor's place, each text box's text and
    # the scene last drawn (so a redraw is skipped exactly where the running one skips it)
    STATE_SCHEMA = Record(balls=DoubleBuffer.STATE_SCHEMA, cursor_at=Opt(Tuple((Int(), Int()))),
                          boxes=Record(**{b: SHOWN for b in BOXES}), last_scene=SCENE)

    def state_values(self) -> dict[str, Any]:
        scene = None
        if self.last_scene is not None:
            pos, on, (lines, dots, rings) = self.last_scene
            scene = {"pos": pos, "on": on, "lines": _ints(lines), "dots": _ints(dots),
                     "rings": _ints(rings)}
        return {"balls": self.balls.state_values(), "cursor_at": self.cursor_at,
                "boxes": {b: getattr(self, b).shown for b in BOXES}, "last_scene": scene}

    def check_state_values(self, values: dict[str, Any]) -> Callable[[], None]:
        put_balls = self.balls.check_state_values(values["balls"])
        scene = values["last_scene"]

        def put() -> None:
            put_balls()
            self.cursor_at = values["cursor_at"]
            for b in BOXES:
                box = getattr(self, b)
                box.shown = values["boxes"][b]
                box.area.text = "" if box.shown is None else box.shown[0]
            self.last_scene = None if scene is None else (
                scene["pos"], scene["on"],
                (tuple(scene["lines"]), tuple(scene["dots"]), tuple(scene["rings"])))
        return put

    def __init__(self, client: RainbowClient, view: TableView) -> None:
        c = self.client = client
        self.view = view
        c.set_lut(PAGE * 256, page_colours())
        self.table_pad = c.create_pad(SCREEN_W, SCREEN_H, 3, plane=0, lut_page=PAGE)
        c.map(SCREEN, self.table_pad, 0, 0, PRIORITY)
        self.balls = DoubleBuffer(c, SCREEN, SCREEN_W, SCREEN_H, 4, plane=3, lut_page=PAGE,
                                  priority=PRIORITY)
        self.cursor_pad = c.create_pad(CURSOR_SIZE, CURSOR_SIZE, 1, plane=7, lut_page=PAGE)
        half = CURSOR_SIZE // 2
        c.line(self.cursor_pad, 0, half, CURSOR_SIZE - 1, half, 1)
        c.line(self.cursor_pad, half, 0, half, CURSOR_SIZE - 1, 1)
        self.cursor_arc = c.map(SCREEN, self.cursor_pad, 0, 0, PRIORITY)
        self.cursor_at: tuple[int, int] | None = None
        self.help = TextBox(c, layout.HELP_BOX, 2)
        self.info = TextBox(c, layout.INFO_BOX, 3)
        self.step_box = TextBox(c, layout.STEP_BOX, 4)
        self.status = TextBox(c, layout.STATUS_BOX, 5)
        self.frame_box = TextBox(c, layout.FRAME_BOX, 6)
        self.draw_table()
        self.last_scene: tuple[bytes, bytes, object] | None = None

    # -- the table pad, drawn once ------------------------------------------------------
    def draw_table(self) -> None:
        c, v, t = self.client, self.view, self.view.table
        pad = self.table_pad
        c.clear(pad, BACKGROUND)
        x, y, w, h = v.play_rect
        k, wd = layout.CUSHION_PX, layout.WOOD_PX
        c.rect(pad, x - k - wd, y - k - wd, w + 2 * (k + wd), h + 2 * (k + wd), WOOD)
        c.rect(pad, x - k, y - k, w + 2 * k, h + 2 * k, CUSHION)
        c.rect(pad, x, y, w + 1, h + 1, CLOTH)
        for p in t.pockets:
            a, b = v.to_screen(p.ax, p.ay), v.to_screen(p.bx, p.by)
            ox, oy = p.outward[0], -p.outward[1]  # unit vector, screen y down
            depth = k + wd * 0.6
            quad = [a, b, (b[0] + ox * depth, b[1] + oy * depth),
                    (a[0] + ox * depth, a[1] + oy * depth)]
            c.polygon(pad, [(round(px), round(py)) for px, py in quad], POCKET)
            mx, my = v.to_pixel(*p.centre)
            r = round(p.width * v.scale / 2)
            c.circle(pad, round(mx + ox * (k * 0.7)), round(my + oy * (k * 0.7)), r, POCKET)
        # the baulk line and the D (a semicircle on the baulk side)
        bx0, by0 = v.to_pixel(t.baulk_line_m, 0.0)
        bx1, by1 = v.to_pixel(t.baulk_line_m, t.width_m)
        c.line(pad, bx0, by0, bx1, by1, MARKING)
        cx, cy = t.spots[BROWN]  # the D's centre
        pts = [v.to_pixel(cx - t.d_radius_m * math.sin(a), cy + t.d_radius_m * math.cos(a))
               for a in np.linspace(0.0, math.pi, 41)]
        for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
            c.line(pad, x0, y0, x1, y1, MARKING)
        for sx, sy in t.spots.values():
            px, py = v.to_pixel(sx, sy)
            c.rect(pad, px - 1, py - 1, 2, 2, MARKING)

    # -- the balls: draw into the back pad, then swap -----------------------------------
    def draw_balls(self, pos: np.ndarray, on_table: np.ndarray, overlay: Overlay) -> bool:
        """Redraw the back pad and swap; skipped (returns False) if nothing changed."""
        key = (np.ascontiguousarray(pos).tobytes(), np.ascontiguousarray(on_table).tobytes(),
               (tuple(overlay.lines), tuple(overlay.dots), tuple(overlay.rings)))
        if key == self.last_scene:
            return False
        self.last_scene = key
        c, v = self.client, self.view
        back = self.balls.back
        c.clear(back, 0)
        r = v.ball_radius_px
        for cx, cy, rr, val in overlay.rings:
            c.circle(back, cx, cy, rr, val)
        for i in range(N_BALLS):
            if on_table[i]:
                px, py = v.to_pixel(pos[i, 0], pos[i, 1])
                c.circle(back, px, py, r, ball_value(i))
        for x0, y0, x1, y1, val in overlay.lines:
            c.line(back, x0, y0, x1, y1, val)
        for x0, y0, val in overlay.dots:
            c.point(back, x0, y0, val)
        self.balls.swap()
        return True

    def move_cursor(self, x: int, y: int) -> None:
        if self.cursor_at != (x, y):
            half = CURSOR_SIZE // 2
            self.client.move(self.cursor_arc, x - half, y - half)
            self.cursor_at = (x, y)
