"""The panning "super pad" of §7.3: one large pad mapped four times into a cluster.

The pad holds the world modulo its size (a torus). The four arcs place copies so they tile
the view; panning only changes arc positions. Before each frame the program is asked to
draw exactly the world strips that are about to come into view, into the pad positions
they wrap to, so the picture scrolls without any block copy.
"""

from __future__ import annotations

from collections.abc import Callable

from camlab88.protocols.rainbow.client import RainbowClient

# draw(world_x, world_y, w, h, pad_x, pad_y): fill that pad rectangle with that world area.
DrawStrip = Callable[[int, int, int, int, int, int], None]


def _wrapped(a: int, n: int, size: int) -> list[tuple[int, int, int]]:
    """[a, a+n) on a circle of ``size``: pieces (world start, length, pad start)."""
    out = []
    while n > 0:
        p = a % size
        k = min(n, size - p)
        out.append((a, k, p))
        a, n = a + k, n - k
    return out


class SuperPad:
    def __init__(self, client: RainbowClient, parent: int, view_w: int, view_h: int,
                 pad_w: int, pad_h: int, depth: int, draw: DrawStrip, plane: int = 0,
                 lut_page: int = 0, priority: int = 0, view_x: int = 0, view_y: int = 0) -> None:
        if pad_w < view_w or pad_h < view_h:
            raise ValueError("the super pad must be at least as large as the view it fills")
        self.client = client
        self.view_w, self.view_h = view_w, view_h
        self.pad_w, self.pad_h = pad_w, pad_h
        self.draw = draw
        self.pad = client.create_pad(pad_w, pad_h, depth, plane, lut_page)
        self.arcs = [client.map(parent, self.pad, 0, 0, priority) for _ in range(4)]
        self.vx, self.vy = view_x, view_y
        self.drawn_pixels = 0
        self._fill(view_x, view_y, view_w, view_h)
        self._place()

    def _fill(self, wx: int, wy: int, w: int, h: int) -> None:
        for ax, kx, px in _wrapped(wx, w, self.pad_w):
            for ay, ky, py in _wrapped(wy, h, self.pad_h):
                self.draw(ax, ay, kx, ky, px, py)
                self.drawn_pixels += kx * ky

    def _place(self) -> None:
        bx = (self.vx // self.pad_w) * self.pad_w - self.vx
        by = (self.vy // self.pad_h) * self.pad_h - self.vy
        for n, arc in enumerate(self.arcs):
            self.client.move(arc, bx + (n % 2) * self.pad_w, by + (n // 2) * self.pad_h)

    def pan_to(self, vx: int, vy: int) -> None:
        """Show the world from (vx, vy): draw the newly exposed strips, then move the arcs."""
        dx, dy = vx - self.vx, vy - self.vy
        if abs(dx) >= self.view_w or abs(dy) >= self.view_h:
            self._fill(vx, vy, self.view_w, self.view_h)  # a jump: everything is new
        else:
            if dx > 0:
                self._fill(self.vx + self.view_w, vy, dx, self.view_h)
            elif dx < 0:
                self._fill(vx, vy, -dx, self.view_h)
            # rows newly exposed, over the columns not already covered above
            cx0 = max(vx, self.vx)
            cx1 = min(vx, self.vx) + self.view_w
            if cx1 > cx0 and dy > 0:
                self._fill(cx0, self.vy + self.view_h, cx1 - cx0, dy)
            elif cx1 > cx0 and dy < 0:
                self._fill(cx0, vy, cx1 - cx0, -dy)
        self.vx, self.vy = vx, vy
        self._place()

    def pan(self, dx: int, dy: int) -> None:
        self.pan_to(self.vx + dx, self.vy + dy)
