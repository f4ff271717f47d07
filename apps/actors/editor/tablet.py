"""A tablet's stylus as the editor's left button: the whole tablet surface maps onto the
profile pad (absolute, as a digitiser over a drawing), the pen touching (first button or
pressure) is the left button held, leaving proximity lets go."""

from __future__ import annotations

from camlab88.apps.actors.editor import layout as L
from camlab88.protocols.rainbow.events import LEFT, MouseEvent, TabletEvent

DEFAULT_EXTENT = (2200, 1700)  # tablet units when the command knows no model's range


class TabletPen:
    def __init__(self, extent: tuple[int, int] = DEFAULT_EXTENT,
                 origin_lower_left: bool = False) -> None:
        self.extent = (max(1, extent[0]), max(1, extent[1]))
        self.flip = origin_lower_left
        self.down = False

    def screen(self, e: TabletEvent) -> tuple[int, int]:
        x, y, w, h = L.PROFILE
        fx = min(max(e.x / self.extent[0], 0.0), 1.0)
        fy = min(max(e.y / self.extent[1], 0.0), 1.0)
        if self.flip:
            fy = 1.0 - fy
        return x + round(fx * (w - 1)), y + round(fy * (h - 1))

    def mouse_events(self, e: TabletEvent) -> list[MouseEvent]:
        sx, sy = self.screen(e)
        touching = e.proximity and (bool(e.buttons & 1) or e.pressure > 0)
        out = [MouseEvent(e.t_ms, sx, sy, LEFT if self.down else 0)]
        if touching != self.down:
            self.down = touching
            out.append(MouseEvent(e.t_ms, sx, sy, LEFT if touching else 0, 1, touching))
        return out
