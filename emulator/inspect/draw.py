"""Drawing for panels and overlays: text in the ROM font (roms/rainbow_font.txt, 6 x 10
cells), boxes and lines, on (h, w, 3) uint8 numpy images.  No pygame: the same pictures go
to a window, to PNGs and to golden tests."""

from __future__ import annotations

import numpy as np

from camlab88.roms.rainbow_font import load_font

Colour = tuple[int, int, int]
INK: Colour = (230, 230, 230)
DIM: Colour = (140, 140, 150)
PAPER: Colour = (24, 24, 32)
ACCENT: Colour = (255, 200, 60)


def cell() -> tuple[int, int]:
    """(width, height) of one character."""
    cw, ch, _ = load_font()
    return cw, ch


def text(img: np.ndarray, x: int, y: int, s: str, colour: Colour = INK) -> int:
    """Draw ``s`` with its top-left corner at (x, y), clipped to ``img``; returns the x after
    it.  Characters the font lacks are drawn as '?'."""
    cw, ch, glyphs = load_font()
    h, w = img.shape[:2]
    for c in s:
        g = glyphs.get(ord(c), glyphs.get(ord("?")))
        if g is not None and x < w and y < h and x + cw > 0 and y + ch > 0:
            gx0, gy0 = max(0, -x), max(0, -y)
            gx1, gy1 = min(cw, w - x), min(ch, h - y)
            region = img[y + gy0:y + gy1, x + gx0:x + gx1]
            region[g[gy0:gy1, gx0:gx1]] = colour
        x += cw
    return x


def fill(img: np.ndarray, x: int, y: int, w: int, h: int, colour: Colour) -> None:
    """A filled rectangle, clipped."""
    H, W = img.shape[:2]
    x0, y0, x1, y1 = max(0, x), max(0, y), min(W, x + w), min(H, y + h)
    if x1 > x0 and y1 > y0:
        img[y0:y1, x0:x1] = colour


def frame_box(img: np.ndarray, x: int, y: int, w: int, h: int, colour: Colour) -> None:
    """A one-pixel rectangle outline, clipped."""
    fill(img, x, y, w, 1, colour)
    fill(img, x, y + h - 1, w, 1, colour)
    fill(img, x, y, 1, h, colour)
    fill(img, x + w - 1, y, 1, h, colour)


def line(img: np.ndarray, x0: int, y0: int, x1: int, y1: int, colour: Colour) -> None:
    """A straight line (sampled at every pixel step), clipped."""
    n = max(abs(x1 - x0), abs(y1 - y0), 1)
    xs = np.rint(np.linspace(x0, x1, n + 1)).astype(int)
    ys = np.rint(np.linspace(y0, y1, n + 1)).astype(int)
    H, W = img.shape[:2]
    ok = (xs >= 0) & (xs < W) & (ys >= 0) & (ys < H)
    img[ys[ok], xs[ok]] = colour


def shade(img: np.ndarray, x: int, y: int, w: int, h: int, keep: float = 0.25) -> None:
    """Darken a rectangle (an overlay's background: the screen shows through)."""
    H, W = img.shape[:2]
    x0, y0, x1, y1 = max(0, x), max(0, y), min(W, x + w), min(H, y + h)
    if x1 > x0 and y1 > y0:
        img[y0:y1, x0:x1] = (img[y0:y1, x0:x1] * keep).astype(np.uint8)


def canvas(w: int, h: int, colour: Colour = PAPER) -> np.ndarray:
    img = np.empty((h, w, 3), np.uint8)
    img[:] = colour
    return img
