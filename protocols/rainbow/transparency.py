"""The Appendix I transparency example (suggested by Neil Wiseman), as a program.

A red polygon anti-aliased against black in a 5-bit pad (planes 3..7) and a pad of eight
colour splodges in 3 bits (planes 0..2), mapped at equal priority. Where they overlap the
5 + 3 bits are concatenated into one 8-bit word indexing a 256-entry table arranged so the
polygon is opaque, its black background transparent and its edge shades mix with the splodge
beneath. The model's tie rule takes the larger LUT page, so the polygon's page holds that
256-entry table; its column for splodge value 0 (black) is the polygon's own 32 shades of red
to black, and the splodge pad's page holds the splodges' 8-entry table.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.protocols.rainbow.antialias import coverage
from camlab88.protocols.rainbow.client import SCREEN, RainbowClient

RED = np.array([255, 0, 0])
SPLODGES = np.array([[0, 0, 0], [40, 90, 255], [40, 200, 60], [250, 220, 40],
                     [170, 60, 220], [30, 210, 220], [255, 140, 30], [240, 240, 240]])
SPLODGE_PAGE, POLYGON_PAGE = 1, 2
POLY_PLANE, SPLODGE_PLANE = 3, 0
POLY_W, POLY_H = 240, 200
SPLODGE_W, SPLODGE_H = 360, 260


def mix(shade: int, splodge: int) -> np.ndarray:
    """The colour for polygon shade 0..31 over splodge value 0..7."""
    a = shade / 31
    return np.rint(a * RED + (1 - a) * SPLODGES[splodge]).astype(np.int64)


def combined_table() -> np.ndarray:
    """256 entries indexed by (shade << 3) | splodge."""
    return np.array([mix(w >> 3, w & 7) for w in range(256)])


def polygon_points(w: int = POLY_W, h: int = POLY_H) -> list[tuple[float, float]]:
    return [(0.12 * w, 0.2 * h), (0.85 * w, 0.07 * h), (0.93 * w, 0.72 * h),
            (0.5 * w, 0.95 * h), (0.2 * w, 0.8 * h), (0.36 * w, 0.5 * h)]


def splodge_image(w: int = SPLODGE_W, h: int = SPLODGE_H) -> np.ndarray:
    """Seven round splodges of colour on black (value 0)."""
    img = np.zeros((h, w), np.uint8)
    yy, xx = np.mgrid[0:h, 0:w]
    for v in range(1, 8):
        cx = (v * 97) % (w - 60) + 30
        cy = (v * 53) % (h - 60) + 30
        img[(xx - cx) ** 2 + (yy - cy) ** 2 <= (28 + 4 * v) ** 2] = v
    return img


@dataclass
class TransparencyExample:
    poly_pad: int
    splodge_pad: int
    poly_arc: int
    splodge_arc: int


def build(client: RainbowClient, parent: int = SCREEN, poly_at: tuple[int, int] = (100, 80),
          splodge_at: tuple[int, int] = (40, 40), priority: int = 0,
          poly_size: tuple[int, int] = (POLY_W, POLY_H),
          splodge_size: tuple[int, int] = (SPLODGE_W, SPLODGE_H)) -> TransparencyExample:
    """Build the example; smaller sizes let it fit the strict (512 x 256) video memory."""
    c = client
    (pw, ph), (sw, sh) = poly_size, splodge_size
    spl = c.create_pad(sw, sh, 3, SPLODGE_PLANE, SPLODGE_PAGE)
    poly = c.create_pad(pw, ph, 5, POLY_PLANE, POLYGON_PAGE)
    c.set_lut(SPLODGE_PAGE * 256, [tuple(int(v) for v in col) for col in SPLODGES])
    c.set_lut(POLYGON_PAGE * 256, [tuple(int(v) for v in col) for col in combined_table()])
    c.put_pixels(spl, 0, 0, splodge_image(sw, sh))
    c.put_pixels(poly, 0, 0, coverage(polygon_points(pw, ph), pw, ph, levels=32))
    sa = c.map(parent, spl, *splodge_at, priority)
    pa = c.map(parent, poly, *poly_at, priority)
    return TransparencyExample(poly, spl, pa, sa)
