"""Where things go on the 768 x 576 Rainbow screen, and the table <-> screen mapping.

The table is seen from directly overhead (orthographic, §6.2.2) with the baulk end on the
left: model x (up the table) runs along screen x; model +y is to the left of a player
looking up the table, which is screen up, so screen y = top + (width - y) * scale.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from camlab88.apps.snooker.table import Table

SCREEN_W, SCREEN_H = 768, 576

# Message areas: help top left, selected ball top right (§6.2.2); the stepping sub-menu of
# "alter a different frame" below it; the frame number bottom right (§6.2.1).
HELP_BOX = (4, 4, 420, 60)
INFO_BOX = (430, 4, 334, 60)
STEP_BOX = (604, 68, 160, 38)
STATUS_BOX = (4, 540, 560, 32)
FRAME_BOX = (624, 540, 140, 32)

CUSHION_PX = 9
WOOD_PX = 13


@dataclass(frozen=True)
class TableView:
    table: Table
    scale: float  # pixels per metre
    left: int  # screen x of the baulk cushion face
    top: int  # screen y of the left (y = width) cushion face

    @classmethod
    def fit(cls, table: Table, width_px: int = 700, top: int = 118,
            max_height_px: int = 380) -> TableView:
        scale = min(width_px / table.length_m, max_height_px / table.width_m)
        left = (SCREEN_W - round(table.length_m * scale)) // 2
        return cls(table, scale, left, top)

    def to_screen(self, x: float, y: float) -> tuple[float, float]:
        return (self.left + x * self.scale, self.top + (self.table.width_m - y) * self.scale)

    def to_pixel(self, x: float, y: float) -> tuple[int, int]:
        sx, sy = self.to_screen(x, y)
        return (math.floor(sx + 0.5), math.floor(sy + 0.5))

    def to_table(self, sx: float, sy: float) -> tuple[float, float]:
        return ((sx - self.left) / self.scale, self.table.width_m - (sy - self.top) / self.scale)

    def vector_to_screen(self, vx: float, vy: float) -> tuple[float, float]:
        return (vx * self.scale, -vy * self.scale)

    def vector_to_table(self, dx: float, dy: float) -> tuple[float, float]:
        return (dx / self.scale, -dy / self.scale)

    @property
    def ball_radius_px(self) -> int:
        return max(2, round(self.table.radius * self.scale))

    @property
    def play_rect(self) -> tuple[int, int, int, int]:
        """Screen rectangle of the playing surface (x, y, w, h)."""
        return (self.left, self.top, round(self.table.length_m * self.scale),
                round(self.table.width_m * self.scale))
