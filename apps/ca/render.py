"""Colours of life-forms and a plain RGB rendering of part of the plane (pure numpy).

The interactive Rainbow program draws with its own device calls; this module gives it (and
the headless ``--png`` option) the thesis's colour rules: a life-form's ``COLOUR`` from the
rule file, otherwise a unique colour per life-form; monochrome shows every living cell
white on black (section 7.3.2, "Alter display").
"""

from __future__ import annotations

import colorsys

import numpy as np

from camlab88.apps.ca.engine import SIDE, Engine, Rect
from camlab88.apps.ca.rules import RuleSet

# Section 7.4.1: type 1 is "green by default", type 2 "red", type 3 "blue".
FIRST_COLOURS = [(0, 255, 0), (255, 0, 0), (0, 0, 255), (255, 255, 0), (0, 255, 255),
                 (255, 0, 255), (255, 255, 255), (255, 128, 0)]


def default_colour(form: int) -> tuple[int, int, int]:
    """A distinct colour per life-form: the thesis's first three, then hue steps."""
    if 1 <= form <= len(FIRST_COLOURS):
        return FIRST_COLOURS[form - 1]
    h = (0.12 + 0.618034 * form) % 1.0
    r, g, b = colorsys.hsv_to_rgb(h, 0.75, 1.0)
    return int(r * 255), int(g * 255), int(b * 255)


def palette(rules: RuleSet | None, count: int) -> np.ndarray:
    """(count + 1, 3) uint8 colours, index = life-form, row 0 = dead (black)."""
    out = np.zeros((count + 1, 3), np.uint8)
    for t in range(1, count + 1):
        form = rules.forms.get(t) if rules is not None else None
        if form is not None and form.invisible:
            continue  # drawn as a dead cell (section 7.4.2's invisible cells)
        out[t] = form.colour if form is not None and form.colour else default_colour(t)
    return out


MAX_PIXELS = 1 << 26  # 64 megapixels: 192 MB of RGB


def check_size(rect: Rect, zoom: int) -> None:
    """Refuse a picture too large to hold, before any work."""
    pixels = rect.width * rect.height * zoom * zoom
    if zoom < 1 or pixels > MAX_PIXELS:
        raise ValueError(f"a {rect.width * zoom} x {rect.height * zoom} pixel picture "
                         f"(zoom {zoom}) is more than {MAX_PIXELS} pixels; pick a smaller area "
                         "or zoom")


def render(engine: Engine, rect: Rect, zoom: int = 4, monochrome: bool = False,
           gaps: bool = True) -> np.ndarray:
    """(h, w, 3) image of ``rect``, each cell ``zoom`` pixels square, with a one-pixel gap
    between cells at zoom >= 4 as on the thesis's screen. A picture over MAX_PIXELS raises
    ValueError saying how big it would be (a soup spread over the 65536-cell plane at zoom
    4 would be 68 billion pixels)."""
    check_size(rect, zoom)
    xs, ys, ts = engine.cells_in_rect(rect)
    top = int(ts.max()) if ts.size else 0
    pal = palette(engine.rules, max(top, 1))
    if monochrome:
        pal[1:][pal[1:].any(axis=1)] = 255  # white, but invisible forms stay dead-black
    cells = np.zeros((rect.height, rect.width, 3), np.uint8)
    cells[(ys - rect.y0) % SIDE, (xs - rect.x0) % SIDE] = pal[ts]  # rect may cross the seam
    img = np.repeat(np.repeat(cells, zoom, axis=0), zoom, axis=1)
    if gaps and zoom >= 4:
        img[zoom - 1::zoom, :, :] = 0
        img[:, zoom - 1::zoom, :] = 0
    return img
