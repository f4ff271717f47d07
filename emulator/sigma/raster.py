"""Firmware raster operations on the plane store (numba): vectors, spans, boundary fill.

The plane store is a 2-D uint8 array indexed [y, x] with device y pointing up (row 0 is the
bottom of the drawing area). Every write goes through the plane write mask:
``new = (old & ~wm) | (colour & wm)``. Pixels outside the store are clipped silently.

The kernels are compiled lazily: importing this module does not import numba (about a
quarter of a second); the first call of any kernel compiles (or loads from the numba cache)
all of them, so a run that never draws never pays for numba.
"""

from __future__ import annotations

import threading

import numpy as np
from camlab88.base.lazy_kernels import LazyKernels


def _announce() -> None:
    from camlab88.base.kernel_notice import announce_compiles

    # one line on stderr if the cache is cold; ~2 s is the measured cold compile
    announce_compiles("Sigma raster", 2.0, __name__, "camlab88.protocols.sigma.abbreviated",
                      completion="camlab88.emulator.sigma.kernel_warmup:compile_kernels")


# Every kernel must be called with one set of argument types only: numba's on-disk cache
# numbers a function's signatures 1, 2, ... and two processes compiling *different*
# signatures at once can leave the index naming one signature's file holding the
# other's code (docs/development.md, "numba's cache").
_kernels = LazyKernels(globals(), _announce, nogil=True)
_kernel = _kernels.kernel

FRACTION_BITS = 12  # the reconstructed DDA's fixed-point fraction (see firmware_line_points)
HALF = 1 << (FRACTION_BITS - 1)


@_kernel
def _put(pix, x, y, colour, wm):  # numba kernel
    if 0 <= y < pix.shape[0] and 0 <= x < pix.shape[1]:
        pix[y, x] = (pix[y, x] & ~wm) | (colour & wm)


@_kernel
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


@_kernel
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


def firmware_line_points(x0: int, y0: int, x1: int, y1: int) -> list[tuple[int, int]]:
    """The pixels the reconstructed firmware vector sets, in order (for tests and docs)."""
    size = max(abs(x0), abs(x1), abs(y0), abs(y1)) + 1
    pix = np.zeros((size, size), dtype=np.uint8)
    draw_line(pix, x0, y0, x1, y1, 1, 0xFF, 0, 0, 0, False)
    ys, xs = np.nonzero(pix)
    return sorted(zip(xs.tolist(), ys.tolist()))


def bresenham_points(x0: int, y0: int, x1: int, y1: int) -> list[tuple[int, int]]:
    """Bresenham's (1965) algorithm, the reference the firmware disagrees with (thesis 6.4.1)."""
    dx, dy = abs(x1 - x0), -abs(y1 - y0)
    sx = 1 if x0 < x1 else -1
    sy = 1 if y0 < y1 else -1
    err = dx + dy
    out = []
    x, y = x0, y0
    while True:
        out.append((x, y))
        if x == x1 and y == y1:
            break
        e2 = 2 * err
        if e2 >= dy:
            err += dy
            x += sx
        if e2 <= dx:
            err += dx
            y += sy
    return sorted(out)


@_kernel
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


@_kernel
def _boundary_fill(pix, sx, sy, colour, wm, boundary, rmask, blocked, stack):
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


_FILL_WORK: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}
_FILL_LOCK = threading.Lock()  # the shared buffers serve one fill at a time


def boundary_fill(pix: np.ndarray, sx: int, sy: int, colour: int, wm: int, boundary: int,
                  rmask: int) -> int:
    """Firmware flood fill (see _boundary_fill). The work buffers — a blocked map and a stack
    of 2 entries per pixel, about 14 MB on the T5688 — are allocated once per area size and
    reused by every later fill, which the kernel fully re-initialises."""
    h, w = pix.shape
    with _FILL_LOCK:
        work = _FILL_WORK.get((h, w))
        if work is None:
            # each pixel is pushed at most twice (from the rows above and below)
            work = (np.empty((h, w), dtype=np.uint8), np.empty(2 * h * w + 16, dtype=np.int32))
            _FILL_WORK[(h, w)] = work
        return _boundary_fill(pix, int(sx), int(sy), int(colour), int(wm), int(boundary),
                              int(rmask), work[0], work[1])


@_kernel
def dot_run(pix, x, y, colours, wm):
    """DJ: one pixel per colour, advancing +X from (x, y); returns the next x."""
    for k in range(colours.shape[0]):
        _put(pix, x, y, np.int64(colours[k]), wm)  # int64: one _put signature
        x += 1
    return x


def ellipse_pixels(cx: int, cy: int, a: float, b: float, width: int, height: int,
                   solid: bool) -> tuple[np.ndarray, int, int]:
    """Pixels of an ellipse with semi-axes a (x) and b (y) centred on (cx, cy), computed only
    inside the drawing area (so a huge ellipse costs no more than the area). Returns
    (mask, x0, y0): the mask's [0, 0] is device pixel (x0, y0)."""
    ra = max(int(np.floor(a + 0.5)), 0)
    rb = max(int(np.floor(b + 0.5)), 0)
    # one pixel of margin so the outline test can see the neighbours of edge pixels
    x0, x1 = max(cx - ra, -1), min(cx + ra, width)
    y0, y1 = max(cy - rb, -1), min(cy + rb, height)
    if x0 > x1 or y0 > y1:
        return np.zeros((0, 0), dtype=bool), 0, 0
    ys = np.arange(y0 - 1, y1 + 2, dtype=np.float64)[:, None] - cy
    xs = np.arange(x0 - 1, x1 + 2, dtype=np.float64)[None, :] - cx
    aa = max(a, 0.5) + 0.5
    bb = max(b, 0.5) + 0.5
    inside = ((xs / aa) ** 2 + (ys / bb) ** 2 <= 1.0) & (np.abs(xs) <= ra) & (np.abs(ys) <= rb)
    if solid:
        shape = inside
    else:
        interior = np.zeros_like(inside)
        interior[1:-1, 1:-1] = (inside[1:-1, 1:-1] & inside[:-2, 1:-1] & inside[2:, 1:-1]
                                & inside[1:-1, :-2] & inside[1:-1, 2:])
        shape = inside & ~interior
    return shape[1:-1, 1:-1], x0, y0


def write_mask_at(pix: np.ndarray, mask: np.ndarray, x0: int, y0: int, colour: int,
                  wm: int) -> None:
    """Write ``colour`` where ``mask`` is set (its [0, 0] at (x0, y0)), clipped, write-masked."""
    h, w = pix.shape
    mh, mw = mask.shape
    ys0, xs0 = max(y0, 0), max(x0, 0)
    ys1, xs1 = min(y0 + mh, h), min(x0 + mw, w)
    if ys0 >= ys1 or xs0 >= xs1:
        return
    m = mask[ys0 - y0:ys1 - y0, xs0 - x0:xs1 - x0]
    region = pix[ys0:ys1, xs0:xs1]
    region[m] = (region[m] & (~wm & 0xFF)) | (colour & wm)
