"""Drawing into pads: the raster primitives of the pad library.

Each primitive works in pad coordinates, clips to the pad, and writes the value into the
pad's own planes only (other planes of the same words are left alone, so pads sharing words
in distinct planes do not disturb each other).
"""

from __future__ import annotations

import numpy as np

from camlab88.emulator.rainbow.errors import RainbowError
from camlab88.emulator.rainbow.graph import Pad
from camlab88.roms.rainbow_font import load_font

MAX_POLYGON_POINTS = 4096
MAX_TEXT = 4096


class Canvas:
    """A pad's rectangle of memory words, seen as pixel values 0..2^depth-1."""

    def __init__(self, words: np.ndarray, pad: Pad) -> None:
        if pad.depth == 0 or pad.alloc is None:
            raise RainbowError(f"pad {pad.id} is virtual (depth 0): it has no pixels to draw")
        a = pad.alloc
        self.pad = pad
        self.w, self.h = pad.width, pad.height
        self.region = words[a.y: a.y + pad.height, a.x: a.x + pad.width]
        self.mask = np.uint8(a.plane_mask)
        self.vmax = (1 << pad.depth) - 1

    def _word(self, value: int) -> np.uint8:
        if not isinstance(value, int) or not 0 <= value <= self.vmax:
            raise RainbowError(
                f"value {value!r} does not fit pad {self.pad.id} of depth {self.pad.depth}"
            )
        return np.uint8(value << self.pad.plane)

    def _put(self, sel, value: int) -> None:
        r = self.region
        r[sel] = (r[sel] & ~self.mask) | self._word(value)

    def _put_points(self, xs: np.ndarray, ys: np.ndarray, value: int) -> None:
        keep = (xs >= 0) & (xs < self.w) & (ys >= 0) & (ys < self.h)
        self._put((ys[keep], xs[keep]), value)

    # -- primitives ------------------------------------------------------------------------
    def read(self, x: int = 0, y: int = 0, w: int | None = None, h: int | None = None):
        w = self.w if w is None else w
        h = self.h if h is None else h
        if x < 0 or y < 0 or w < 0 or h < 0 or x + w > self.w or y + h > self.h:
            raise RainbowError(
                f"block {w}x{h} at ({x},{y}) is outside pad {self.pad.id} ({self.w}x{self.h})"
            )
        return (self.region[y: y + h, x: x + w] & self.mask) >> self.pad.plane

    def clear(self, value: int = 0) -> None:
        self._put(slice(None), value)

    def point(self, x: int, y: int, value: int) -> None:
        self._put_points(np.array([x]), np.array([y]), value)

    def line(self, x0: int, y0: int, x1: int, y1: int, value: int) -> None:
        """Bresenham-equivalent: step the major axis, round the minor to nearest (halves up).

        Only the steps whose major coordinate lies inside the pad are generated, so a line
        with far-away ends costs no more than one across the pad.
        """
        self._word(value)
        dx, dy = x1 - x0, y1 - y0
        n = max(abs(dx), abs(dy))
        if n == 0:
            self._put_points(np.array([x0]), np.array([y0]), value)
            return
        major_x = abs(dx) >= abs(dy)
        m0, dm, size = (x0, dx, self.w) if major_x else (y0, dy, self.h)
        step = 1 if dm > 0 else -1
        # t such that 0 <= m0 + step * t < size, within 0..n
        lo, hi = (-m0, size - 1 - m0) if step > 0 else (m0 - size + 1, m0)
        lo, hi = max(lo, 0), min(hi, n)
        if lo > hi:
            return
        t = np.arange(lo, hi + 1, dtype=np.int64)
        major = m0 + step * t
        if major_x:
            self._put_points(major, y0 + (2 * dy * t + n) // (2 * n), value)
        else:
            self._put_points(x0 + (2 * dx * t + n) // (2 * n), major, value)

    def rect(self, x: int, y: int, w: int, h: int, value: int, filled: bool = True) -> None:
        if w <= 0 or h <= 0:
            return
        if not filled:
            self.rect(x, y, w, 1, value)
            self.rect(x, y + h - 1, w, 1, value)
            self.rect(x, y, 1, h, value)
            self.rect(x + w - 1, y, 1, h, value)
            return
        xa, ya = max(x, 0), max(y, 0)
        xb, yb = min(x + w, self.w), min(y + h, self.h)
        if xa < xb and ya < yb:
            self._put((slice(ya, yb), slice(xa, xb)), value)

    def polygon(self, points: list[tuple[int, int]], value: int) -> None:
        """Filled, even-odd rule, sampled at pixel centres, one scan line at a time."""
        if not 3 <= len(points) <= MAX_POLYGON_POINTS:
            raise RainbowError(f"a polygon needs 3..{MAX_POLYGON_POINTS} points, got {len(points)}")
        word = self._word(value)
        p = np.array(points, dtype=np.float64)
        q = np.roll(p, -1, axis=0)
        keep = p[:, 1] != q[:, 1]  # horizontal edges never cross a scan line's centre
        x0, y0, x1, y1 = p[keep, 0], p[keep, 1], q[keep, 0], q[keep, 1]
        ya = max(int(np.floor(p[:, 1].min())), 0)
        yb = min(int(np.ceil(p[:, 1].max())) + 1, self.h)
        centres = np.arange(self.w) + 0.5
        for y in range(ya, yb):
            cy = y + 0.5
            hit = (y0 > cy) != (y1 > cy)
            if not hit.any():
                continue
            xs = np.sort(x0[hit] + (cy - y0[hit]) * (x1[hit] - x0[hit]) / (y1[hit] - y0[hit]))
            # a pixel centre with an odd number of crossings to its right is inside
            inside = (len(xs) - np.searchsorted(xs, centres, side="right")) % 2 == 1
            row = self.region[y]
            row[inside] = (row[inside] & ~self.mask) | word

    def circle(self, cx: int, cy: int, r: int, value: int) -> None:
        """Filled disc of the pixels whose centres lie within r of (cx, cy): row spans."""
        if r < 0:
            raise RainbowError(f"circle radius {r} is negative")
        word = self._word(value)
        ya, yb = max(cy - r, 0), min(cy + r, self.h - 1)  # only rows inside the pad
        if ya > yb:
            return
        dy = np.arange(ya, yb + 1, dtype=np.int64) - cy
        half = np.floor(np.sqrt(np.maximum(r * r - dy * dy, 0).astype(np.float64)))
        for y, hw in zip((dy + cy).tolist(), half.astype(np.int64).tolist()):
            xa, xb = max(cx - hw, 0), min(cx + hw + 1, self.w)
            if xa < xb:
                row = self.region[y, xa:xb]
                row[:] = (row & ~self.mask) | word

    def text(self, x: int, y: int, s: str, value: int, scale: int = 1) -> int:
        """Draw ink pixels only (the paper stays as it was); returns the width drawn."""
        if len(s) > MAX_TEXT:
            raise RainbowError(f"text longer than {MAX_TEXT} characters")
        if not 1 <= scale <= 16:
            raise RainbowError(f"text scale {scale} must be 1..16")
        cw, ch, glyphs = load_font()
        self._word(value)
        for n, c in enumerate(s):
            g = glyphs.get(ord(c), glyphs[ord("?")])
            if scale > 1:
                g = np.kron(g, np.ones((scale, scale), bool))
            ys, xs = np.nonzero(g)
            self._put_points(xs + x + n * cw * scale, ys + y, value)
        return len(s) * cw * scale

    def put(self, x: int, y: int, values: np.ndarray) -> None:
        """A pixel block (clipped to the pad); values above the pad's depth are an error."""
        values = np.asarray(values)
        if values.ndim != 2:
            raise RainbowError("a pixel block must be 2-D")
        if values.size and int(values.max()) > self.vmax:
            raise RainbowError(
                f"pixel value {int(values.max())} does not fit pad {self.pad.id} "
                f"of depth {self.pad.depth}"
            )
        h, w = values.shape
        xa, ya = max(x, 0), max(y, 0)
        xb, yb = min(x + w, self.w), min(y + h, self.h)
        if xa >= xb or ya >= yb:
            return
        v = values[ya - y: yb - y, xa - x: xb - x].astype(np.uint8) << np.uint8(self.pad.plane)
        sub = self.region[ya:yb, xa:xb]
        sub[:] = (sub & ~self.mask) | v
