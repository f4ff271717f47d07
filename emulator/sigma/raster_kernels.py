"""The Sigma firmware's raster kernels (numba): vectors, spans, rectangles, boundary fill,
dot runs, on the plane store (see emulator/sigma/raster.py, which names them and holds the
Python around them).  Imported on a kernel's first use (raster.py), so a run that never
draws never imports numba (about a quarter of a second).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from camlab88.base.kernel_notice import announce_compiles

# one line on stderr if the cache is cold; ~2 s is the measured cold compile
announce_compiles("Sigma raster", 2.0, __name__, "camlab88.protocols.sigma.abbreviated",
                  completion="camlab88.emulator.sigma.kernel_warmup:compile_kernels")

# Every kernel is called with one set of argument types only: numba's on-disk cache
# numbers a function's signatures 1, 2, ... and two processes compiling *different*
# signatures at once can leave the index naming one signature's file holding the
# other's code (docs/development.md, "numba's cache").
FRACTION_BITS = 12  # the reconstructed DDA's fixed-point fraction (see firmware_line_points)
HALF = 1 << (FRACTION_BITS - 1)


@njit(cache=True, nogil=True)
def _put(pix, x, y, colour, wm):  # numba kernel
    if 0 <= y < pix.shape[0] and 0 <= x < pix.shape[1]:
        pix[y, x] = (pix[y, x] & ~wm) | (colour & wm)


@njit(cache=True, nogil=True)
def draw_line(pix, x0, y0, x1, y1, colour, wm, dash, dash_len, phase, skip_first):
    """Reconstructed firmware vector: a 12-bit fixed-point DDA, not Bresenham.

    The major axis steps one pixel at a time; the minor axis adds the slope truncated to
    1/4096 to an accumulator that starts at one half, and takes its integer part. The
    truncation lets the steps fall up to 0.5 pixel later along the line than Bresenham's
    rounding would, so the two disagree on many long shallow lines while every endpoint
    (vectors up to 2047 steps) is still hit exactly.

    ``dash``/``dash_len``: the pattern (MSB first, 1 = on) and its length in bits, 0 for a
    solid line; ``phase`` is where the pattern stands and the new phase is returned, so a
    pattern continues over consecutive vectors. ``skip_first`` leaves out the start pixel
    (it is the end pixel of the previous vector of a polyline).
    """
    dx = x1 - x0
    dy = y1 - y0
    sx = 1 if dx >= 0 else -1
    sy = 1 if dy >= 0 else -1
    adx = dx * sx
    ady = dy * sy
    if adx >= ady:
        n = adx
        slope = (ady << FRACTION_BITS) // adx if adx else 0
    else:
        n = ady
        slope = (adx << FRACTION_BITS) // ady
    start = 1 if skip_first else 0
    for i in range(start, n + 1):
        minor = (HALF + i * slope) >> FRACTION_BITS
        if adx >= ady:
            x = x0 + sx * i
            y = y0 + sy * minor
        else:
            x = x0 + sx * minor
            y = y0 + sy * i
        if dash_len > 0:
            on = (dash >> (dash_len - 1 - phase)) & 1
            phase += 1
            if phase >= dash_len:
                phase = 0
            if on == 0:
                continue
        _put(pix, x, y, colour, wm)
    return phase


@njit(cache=True, nogil=True)
def draw_polyline(pix, xy, start_x, start_y, colour, wm, dash, dash_len, phase, continuing):
    """Draw from (start_x, start_y) through every point of ``xy``; returns the dash phase."""
    px = start_x
    py = start_y
    cont = continuing
    for k in range(xy.shape[0]):
        # int64 like every other caller's, so draw_line has one signature (see the cache note above)
        x = np.int64(xy[k, 0])
        y = np.int64(xy[k, 1])
        phase = draw_line(pix, px, py, x, y, colour, wm, dash, dash_len, phase, cont)
        cont = True
        px = x
        py = y
    return phase


@njit(cache=True, nogil=True)
def fill_rect(pix, x0, y0, x1, y1, colour, wm):
    """Solid block between two corners, inclusive, clipped."""
    if x0 > x1:
        x0, x1 = x1, x0
    if y0 > y1:
        y0, y1 = y1, y0
    x0 = max(x0, 0)
    y0 = max(y0, 0)
    x1 = min(x1, pix.shape[1] - 1)
    y1 = min(y1, pix.shape[0] - 1)
    keep = ~wm
    c = colour & wm
    for y in range(y0, y1 + 1):
        for x in range(x0, x1 + 1):
            pix[y, x] = (pix[y, x] & keep) | c


@njit(cache=True, nogil=True)
def boundary_fill(pix, sx, sy, colour, wm, boundary, rmask, blocked, stack):
    """Firmware flood fill: spread 4-connected from the seed until pixels whose read-masked
    value equals the boundary colour. Writes go through the write mask. Returns pixels set.

    A span (scan-line) fill over a 'blocked' map (boundary or already filled), so it ends
    even when the fill colour as written (masked) is indistinguishable from the old contents.
    """
    h = pix.shape[0]
    w = pix.shape[1]
    if not (0 <= sx < w and 0 <= sy < h):
        return 0
    b = boundary & rmask
    if (pix[sy, sx] & rmask) == b:
        return 0
    for y in range(h):
        for x in range(w):
            blocked[y, x] = (pix[y, x] & rmask) == b
    cap = stack.shape[0]
    stack[0] = sy * w + sx  # y * w + x: one int32 per entry
    top = 1
    keep = ~wm
    c = colour & wm
    count = 0
    while top > 0:
        top -= 1
        y = stack[top] // w
        x = stack[top] - y * w
        brow = blocked[y]
        if brow[x]:
            continue
        xl = x
        while xl > 0 and not brow[xl - 1]:
            xl -= 1
        xr = x
        while xr < w - 1 and not brow[xr + 1]:
            xr += 1
        row = pix[y]
        for xi in range(xl, xr + 1):
            brow[xi] = 1
            row[xi] = (row[xi] & keep) | c
        count += xr - xl + 1
        for ny in (y - 1, y + 1):
            if ny < 0 or ny >= h:
                continue
            nrow = blocked[ny]
            inrun = False
            for xi in range(xl, xr + 1):
                if nrow[xi]:
                    inrun = False
                elif not inrun:
                    if top < cap:
                        stack[top] = ny * w + xi
                        top += 1
                    inrun = True
    return count


@njit(cache=True, nogil=True)
def dot_run(pix, x, y, colours, wm):
    """DJ: one pixel per colour, advancing +X from (x, y); returns the next x."""
    for k in range(colours.shape[0]):
        _put(pix, x, y, np.int64(colours[k]), wm)  # int64: one _put signature
        x += 1
    return x
