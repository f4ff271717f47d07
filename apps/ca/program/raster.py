"""Pixel values of a rectangle of world pixels (pure numpy; the drawing module sends them).

Values in the grid pads: 0 the gap between cells (shown white as the grid, or as the dead
colour), 1 a dead cell, 1 + t life-form t, 127 + t the *shading* pixels of life-form t
(t = 1..126; larger numbers share values, documented). At zoom 8 and 16 each life-form's
cells carry one of four shading styles; the editing LUT page shows shading pixels darker,
the display pages in the form's own colour, so "a unique relationship between a cell's
value and its colour and style of shading" (section 7.3.1) holds while editing and costs
no redraw. At the subpixel zoom: 1 an empty pixel, 2..255 the density of live cells in it.
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.ca.engine import SIDE, Engine, Rect

GAP, DEAD = 0, 1
FORMS = 126  # distinct life-form values (1..126); shading values follow them
SHADE = FORMS  # shading value = form value + SHADE
MAX_VALUE = 255


def form_slot(t: int | np.ndarray) -> int | np.ndarray:
    """Life-form t (> 0) -> 1..126: its own number up to 126, then shared."""
    t = np.asarray(t, np.int64)
    v = 1 + (t - 1) % FORMS
    return int(v) if v.ndim == 0 else v


def form_value(t: int | np.ndarray) -> int | np.ndarray:
    """Pixel value of life-form t (> 0)."""
    return 1 + form_slot(t)


def shading(t: np.ndarray, i: np.ndarray, j: np.ndarray, z: int) -> np.ndarray:
    """Whether pixel (i, j) of a z-pixel cell of life-form t is a shading pixel.

    Four styles by form number: plain, diagonal stripes, a centre block, horizontal stripes.
    """
    style = (np.asarray(t) - 1) % 4
    diag = (i + j) % 4 == 1
    centre = (abs(2 * i - (z - 2)) <= z // 3) & (abs(2 * j - (z - 2)) <= z // 3)
    stripes = i % 3 == 1
    return ((style == 1) & diag) | ((style == 2) & centre) | ((style == 3) & stripes)


def _pieces(a: int, n: int) -> list[tuple[int, int, int]]:
    """Cell range [a, a+n) modulo the plane as (start, length, offset into the range)."""
    out, off = [], 0
    a %= SIDE
    while n > 0:
        k = min(n, SIDE - a)
        out.append((a, k, off))
        a, n, off = 0, n - k, off + k
    return out


def cell_block(engine: Engine, cx: int, cy: int, w: int, h: int) -> np.ndarray:
    """(h, w) int64 life-forms of the cells from (cx, cy), wrapping round the plane."""
    out = np.zeros((h, w), np.int64)
    for ax, kx, ox in _pieces(cx, min(w, SIDE)):
        for ay, ky, oy in _pieces(cy, min(h, SIDE)):
            xs, ys, ts = engine.cells_in_rect(Rect(ax, ay, ax + kx - 1, ay + ky - 1))
            out[ys - ay + oy, xs - ax + ox] = ts
    return out


def values(engine: Engine, zoom: int, side: int, wx: int, wy: int, w: int,
           h: int) -> np.ndarray:
    """(h, w) uint8 pixel values of world pixels [wx, wx+w) x [wy, wy+h)."""
    if zoom == 0:
        counts = engine.density((wx * side) % SIDE, (wy * side) % SIDE, side, w, h)
        v = np.where(counts > 0, 2 + (counts * 253) // (side * side), DEAD)
        return np.minimum(v, MAX_VALUE).astype(np.uint8)
    cx0, cy0 = wx // zoom, wy // zoom
    cx1, cy1 = (wx + w - 1) // zoom, (wy + h - 1) // zoom
    block = cell_block(engine, cx0, cy0, cx1 - cx0 + 1, cy1 - cy0 + 1)
    cells = np.where(block > 0, form_value(np.maximum(block, 1)), DEAD).astype(np.uint8)
    cols = np.arange(wx, wx + w) // zoom - cx0
    rows = np.arange(wy, wy + h) // zoom - cy0
    out = cells[rows][:, cols]
    if zoom >= 8:
        forms = block[rows][:, cols]
        i = (np.arange(wy, wy + h) % zoom)[:, None]
        j = (np.arange(wx, wx + w) % zoom)[None, :]
        shade = (forms > 0) & shading(np.maximum(forms, 1), i, j, zoom)
        out[shade] += SHADE
    if zoom >= 4:  # one-pixel gap on the right and bottom of each cell
        out[(np.arange(wy, wy + h) % zoom) == zoom - 1, :] = GAP
        out[:, (np.arange(wx, wx + w) % zoom) == zoom - 1] = GAP
    return out
