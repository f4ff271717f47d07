"""Appendix I's shelf unit: semi-transparent components on four pads, translucent by the LUT.

"A three-dimensional representation of a shelf unit constructed from semi-transparent
components and drawn on four separate pads which are able to move independently in real
time.  As the shelf unit slides apart (in a way designed to reinforce its three-dimensional
appearance), the maintenance of realistic translucence is performed by the lookup tables."

The thesis gives no more; this is a reconstruction.  The unit is drawn once, in oblique
projection (depth recedes up and to the right), through the pad library's polygon and line
calls: the back panel, the left side, the right side and the three shelves, each on its own
2-bit pad in its own pair of planes (0-1, 2-3, 4-5, 6-7), all mapped into one cluster at
the same priority.  Where pads overlap their 2-bit values are concatenated into one 8-bit
word; every pad uses one LUT page whose 256 entries hold, for each combination, the colour
of the components seen through one another (0 = none, 1 = a panel's face, 2 = a board's
front edge, 3 = an outline; composited back to front: back panel, shelves, sides).  To slide
the unit apart the program only moves the four arcs — the back panel away along the depth
axis, the shelves towards the viewer along it, the sides outwards — so the pixels are never
redrawn and the lookup table is never rewritten: translucence is kept by the table alone.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camlab88.base.plainstate import Bool, Int, Record
from camlab88.protocols.rainbow.attribute_state import AttributeState
from camlab88.protocols.rainbow.client import SCREEN, SCREEN_H, SCREEN_W, RainbowClient

COMPONENTS = ("back", "left", "right", "shelves")          # plane pairs 0-1, 2-3, 4-5, 6-7
PAINT_ORDER = ("back", "shelves", "left", "right")          # far to near
SHELF_PAGE, BG_PAGE = 9, 8
BACKGROUND = np.array([28, 32, 44])
TINTS = {"back": (120, 170, 255), "left": (255, 190, 90), "right": (255, 190, 90),
         "shelves": (110, 230, 150)}
OUTLINE = {"back": (20, 40, 110), "left": (110, 60, 10), "right": (110, 60, 10),
           "shelves": (15, 90, 40)}
ALPHA = {1: 0.35, 2: 0.7, 3: 1.0}  # face, front edge, outline
FACE, EDGE, LINE = 1, 2, 3
# Full-size geometry (scaled down for the relic's 512 x 256 video memory).
WIDTH, HEIGHT, DEPTH, BOARD = 220, 250, (70, -52), 9
# How far each component slides, in multiples of the depth vector's x and y: the back panel
# away along the depth axis, the shelves towards the viewer along it, the sides outwards.
SLIDE = {"back": (1.1, 1.1), "shelves": (-1.1, -1.1), "left": (-0.9, 0.0),
         "right": (0.9, 0.0)}


def component_colour(name: str, value: int) -> np.ndarray:
    return np.array(OUTLINE[name] if value == LINE else TINTS[name], dtype=np.float64)


def combined_table() -> np.ndarray:
    """(256, 3) colours for every word (back | left << 2 | right << 4 | shelves << 6)."""
    table = np.zeros((256, 3), np.int64)
    for word in range(256):
        out = BACKGROUND.astype(np.float64)
        for name in PAINT_ORDER:
            v = (word >> (2 * COMPONENTS.index(name))) & 3
            if v:
                out = ALPHA[v] * component_colour(name, v) + (1 - ALPHA[v]) * out
        table[word] = np.rint(out)
    return table


@dataclass(frozen=True)
class Geometry:
    """The unit's drawing at one scale, in pad coordinates (all pads the same size)."""

    scale: float

    def _s(self, v: float) -> int:
        return int(round(v * self.scale))

    @property
    def depth(self) -> tuple[int, int]:
        return self._s(DEPTH[0]), self._s(DEPTH[1])

    @property
    def origin(self) -> tuple[int, int]:
        """Front-top-left corner of the unit inside a pad."""
        return self._s(8), self._s(8) - self.depth[1]

    @property
    def pad_size(self) -> tuple[int, int]:
        dx, dy = self.depth
        return self._s(WIDTH + 16) + dx, self._s(HEIGHT + 16) - dy

    def slide(self, name: str, s: float) -> tuple[int, int]:
        """Offset of a component when the unit has slid apart by ``s`` (0 = assembled)."""
        fx, fy = SLIDE[name]
        dx, dy = self.depth
        return int(round(s * fx * dx)), int(round(s * fy * dy))

    def parts(self, name: str) -> list[tuple[str, list[tuple[int, int]], int]]:
        """Drawing calls ("polygon" or "line", points, value) for one component."""
        ox, oy = self.origin
        dx, dy = self.depth
        w, h, b = self._s(WIDTH), self._s(HEIGHT), max(2, self._s(BOARD))
        if name == "back":
            quad = [(ox + dx, oy + dy), (ox + dx + w, oy + dy), (ox + dx + w, oy + dy + h),
                    (ox + dx, oy + dy + h)]
            return [("polygon", quad, FACE), *_outline(quad)]
        if name in ("left", "right"):
            x = ox if name == "left" else ox + w
            side = [(x, oy), (x + dx, oy + dy), (x + dx, oy + dy + h), (x, oy + h)]
            edge = [(x - b // 2, oy), (x + b - b // 2, oy), (x + b - b // 2, oy + h),
                    (x - b // 2, oy + h)]
            return [("polygon", side, FACE), ("polygon", edge, EDGE), *_outline(side)]
        calls = []
        for y in (oy, oy + h // 2, oy + h - b):
            top = [(ox, y), (ox + w, y), (ox + w + dx, y + dy), (ox + dx, y + dy)]
            front = [(ox, y), (ox + w, y), (ox + w, y + b), (ox, y + b)]
            calls += [("polygon", top, FACE), ("polygon", front, EDGE), *_outline(top),
                      *_outline(front)]
        return calls


def _outline(points: list[tuple[int, int]]) -> list[tuple[str, list[tuple[int, int]], int]]:
    return [("line", [points[i], points[(i + 1) % len(points)]], LINE)
            for i in range(len(points))]


@dataclass
class Shelf:
    geometry: Geometry
    cluster: int
    pads: dict[str, int]
    arcs: dict[str, int]
    home: tuple[int, int]

    def positions(self, s: float) -> dict[str, tuple[int, int]]:
        """Where each pad's arc goes when the unit has slid apart by ``s``."""
        hx, hy = self.home
        return {n: (hx + self.geometry.slide(n, s)[0], hy + self.geometry.slide(n, s)[1])
                for n in COMPONENTS}


def scale_for(memory_w: int, memory_h: int) -> float:
    """Full size, or small enough for the pads to fit the video memory."""
    w, h = Geometry(1.0).pad_size
    return min(1.0, (memory_w - 8) / w, (memory_h - 8) / h)


def build(client: RainbowClient, parent: int = SCREEN, at: tuple[int, int] | None = None,
          priority: int = 1, scale: float | None = None) -> Shelf:
    """Draw the four pads once, load the table, map them at equal priority in a cluster."""
    c = client
    if scale is None:
        info = c.hello()
        scale = scale_for(info["memory_w"], info["memory_h"])
    g = Geometry(scale)
    c.set_lut(SHELF_PAGE * 256, [tuple(int(v) for v in col) for col in combined_table()])
    cluster = c.create_cluster(SCREEN_W, SCREEN_H)
    c.map(parent, cluster, 0, 0, priority)
    pw, ph = g.pad_size
    home = at or ((SCREEN_W - pw) // 2, (SCREEN_H - ph) // 2)
    pads, arcs = {}, {}
    for i, name in enumerate(COMPONENTS):
        pad = pads[name] = c.create_pad(pw, ph, 2, plane=2 * i, lut_page=SHELF_PAGE)
        for kind, points, value in g.parts(name):
            if kind == "polygon":
                c.polygon(pad, points, value)
            else:
                (x0, y0), (x1, y1) = points
                c.line(pad, x0, y0, x1, y1, value)
        arcs[name] = c.map(cluster, pad, *home, priority=0)
    return Shelf(g, cluster, pads, arcs, home)


def sliding(t: int, period: int = 200) -> float:
    """0 (assembled) .. 1 (apart) and back, smoothly, over ``period`` frames."""
    return 0.5 - 0.5 * math.cos(2 * math.pi * (t % period) / period)


class ShelfDemo(AttributeState):
    """The program: a background, the shelf unit sliding apart and together again, for
    ever; the left mouse button pauses it.  Each frame sends four moves and nothing else."""

    def __init__(self, client: RainbowClient) -> None:
        c = self.client = client
        c.set_lut(BG_PAGE * 256, [tuple(int(v) for v in BACKGROUND)])
        bg = c.create_pad(SCREEN_W, SCREEN_H, 0, lut_page=BG_PAGE)
        c.map(SCREEN, bg, 0, 0, priority=0)
        self.shelf = build(c)
        self.t = 0
        self.paused = False

    # its declared state (emulator.harness.program_state); the pads are the Rainbow's
    STATE_VERSION = 1
    STATE_SCHEMA = Record(t=Int(0), paused=Bool())

    def step(self) -> tuple[int, int]:
        c = self.client
        for e in c.poll_events():
            if getattr(e, "button", None) == 0 and getattr(e, "pressed", False):
                self.paused = not self.paused
        if not self.paused:
            self.t += 1
        for name, (x, y) in self.shelf.positions(sliding(self.t)).items():
            c.move(self.shelf.arcs[name], x, y)
        return c.wait_frame()
