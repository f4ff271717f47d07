"""What the emulated tablet's window shows: the surface, an inch grid, the ink, the cursor.

Pure numpy (the window module is the only pygame user).  Callers feed it events decoded from
the bytes the tablet sent (by the host reading the pty, or a parser run over the bytes written),
so the picture is evidence that the bytes mean what the mouse did.
"""

from __future__ import annotations

import numpy as np

from camlab88.protocols.tablets.events import TabletEvent, TabletModel

SURFACE = (222, 218, 200)
GRID = (190, 186, 170)
INK = (20, 30, 120)
HOVER = (200, 60, 40)
BORDER = (60, 60, 60)


class TabletView:
    def __init__(self, model: TabletModel, width: int = 640) -> None:
        self.model = model
        aspect = model.max_y / max(model.max_x, 1)
        self.size = (width, max(int(round(width * aspect)), 64))
        self.ink = np.zeros((self.size[1], self.size[0]), dtype=bool)
        self._last: tuple[int, int] | None = None
        self.cursor: tuple[int, int] | None = None
        self.in_prox = False

    def to_pixel(self, event: TabletEvent) -> tuple[int, int]:
        w, h = self.size
        px = round(event.x / max(self.model.max_x, 1) * (w - 1))
        fy = event.y / max(self.model.max_y, 1)
        if self.model.origin == "lower-left":
            fy = 1.0 - fy
        return min(max(px, 0), w - 1), min(max(round(fy * (h - 1)), 0), h - 1)

    def add(self, event: TabletEvent) -> None:
        self.in_prox = event.proximity
        if not event.proximity:
            self._last = None
            return
        p = self.to_pixel(event)
        self.cursor = p
        if event.tip:
            if self._last is not None:
                self._line(self._last, p)
            else:
                self.ink[p[1], p[0]] = True
            self._last = p
        else:
            self._last = None

    def _line(self, a: tuple[int, int], b: tuple[int, int]) -> None:
        n = max(abs(b[0] - a[0]), abs(b[1] - a[1]), 1)
        xs = np.rint(np.linspace(a[0], b[0], n + 1)).astype(int)
        ys = np.rint(np.linspace(a[1], b[1], n + 1)).astype(int)
        for dx in (0, 1):
            for dy in (0, 1):
                self.ink[np.clip(ys + dy, 0, self.size[1] - 1),
                         np.clip(xs + dx, 0, self.size[0] - 1)] = True

    def frame(self) -> np.ndarray:
        w, h = self.size
        img = np.empty((h, w, 3), dtype=np.uint8)
        img[:] = SURFACE
        inch_px = (w - 1) / max(self.model.width_inches, 1e-9)
        if inch_px >= 8:
            for k in np.arange(0.0, w, inch_px):
                img[:, int(k)] = GRID
            rows = np.arange(0.0, h, inch_px)
            if self.model.origin == "lower-left":
                rows = h - 1 - rows
            for k in rows:
                img[int(k), :] = GRID
        img[self.ink] = INK
        img[0, :] = img[-1, :] = img[:, 0] = img[:, -1] = BORDER
        if self.cursor is not None and self.in_prox:
            cx, cy = self.cursor
            img[cy, max(cx - 8, 0) : cx + 9] = HOVER
            img[max(cy - 8, 0) : cy + 9, cx] = HOVER
        return img
