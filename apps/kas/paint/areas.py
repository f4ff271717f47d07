"""The four working areas of figure 3.7 in the T5688's 1536x1024 drawing area (thesis §3.3).

Each area is one quadrant, which the ``KQ`` view order shows full-screen; ``KQ4`` shows the
whole drawing area at half size, so every area appears at a quarter of its size (the
"quarter size version of the shaded image ... in one corner of the screen").  As in the
figure: the painting area bottom right, the colour-mixing area top right, the two double
buffers for replaying finished sequences on the left.  Device y points up, so "bottom" is
the quadrant at y 0-511.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.kas.model import FIELD_H

AREA_W, AREA_H = 768, 512        # one quadrant = one screenful
SCALE = AREA_H / FIELD_H         # pixels per inch: the twelve-field fills the height
PREVIEW = 4                      # KQ4: the whole drawing area at half size


@dataclass(frozen=True)
class Area:
    name: str
    view: int  # the KQ quadrant number

    @property
    def origin(self) -> tuple[int, int]:
        return (self.view % 2) * AREA_W, (self.view // 2) * AREA_H

    def box(self) -> tuple[int, int, int, int]:
        x0, y0 = self.origin
        return x0, y0, x0 + AREA_W - 1, y0 + AREA_H - 1


PAINTING = Area("painting", 1)
MIXING = Area("mixing", 3)
BUFFERS = (Area("buffer 0", 0), Area("buffer 1", 2))
AREAS = (PAINTING, MIXING) + BUFFERS


def to_px(points: np.ndarray) -> np.ndarray:
    """Field inches (centre origin, y up) -> area-local pixels (n, 2) int64, clamped to the
    area so nothing is ever drawn into a neighbouring area (reconstructed: the thesis's
    chains stayed inside the field)."""
    p = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    x = np.clip(np.rint(AREA_W / 2 + p[:, 0] * SCALE), 0, AREA_W - 1)
    y = np.clip(np.rint(AREA_H / 2 + p[:, 1] * SCALE), 0, AREA_H - 1)
    return np.column_stack([x, y]).astype(np.int64)


def to_field(x: float, y: float) -> tuple[float, float]:
    """Area-local pixel -> field inches."""
    return (x - AREA_W / 2) / SCALE, (y - AREA_H / 2) / SCALE


def dedup(px: np.ndarray) -> np.ndarray:
    """Drop points that repeat the previous one (they send characters and draw nothing)."""
    if len(px) < 2:
        return px
    keep = np.ones(len(px), dtype=bool)
    keep[1:] = np.any(px[1:] != px[:-1], axis=1)
    return px[keep]
