"""Firmware raster operations on the plane store (numba): vectors, spans, boundary fill.

The plane store is a 2-D uint8 array indexed [y, x] with device y pointing up (row 0 is the
bottom of the drawing area). Every write goes through the plane write mask:
``new = (old & ~wm) | (colour & wm)``. Pixels outside the store are clipped silently.

The kernels are in ``raster_kernels`` and that module is imported on the first use of one
of their names here (``raster.draw_line``: the module's ``__getattr__``), so importing this
module does not import numba (about a quarter of a second) and a run that never draws
never pays for it.
"""

from __future__ import annotations

import threading
from typing import Any

import numpy as np

KERNELS = ("draw_line", "draw_polyline", "fill_rect", "dot_run")  # raster_kernels' names


def __getattr__(name: str) -> Any:
    """A kernel's name: imports raster_kernels (numba) on first use and keeps the kernel."""
    if name not in KERNELS:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    kernel = getattr(_kernels(), name)
    globals()[name] = kernel  # later uses find it without this function
    return kernel


def _kernels() -> Any:
    from camlab88.emulator.sigma import raster_kernels

    return raster_kernels


def firmware_line_points(x0: int, y0: int, x1: int, y1: int) -> list[tuple[int, int]]:
    """The pixels the reconstructed firmware vector sets, in order (for tests and docs)."""
    size = max(abs(x0), abs(x1), abs(y0), abs(y1)) + 1
    pix = np.zeros((size, size), dtype=np.uint8)
    _kernels().draw_line(pix, x0, y0, x1, y1, 1, 0xFF, 0, 0, 0, False)
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


_FILL_WORK: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}
_FILL_LOCK = threading.Lock()  # the shared buffers serve one fill at a time


def boundary_fill(pix: np.ndarray, sx: int, sy: int, colour: int, wm: int, boundary: int,
                  rmask: int) -> int:
    """Firmware flood fill (see raster_kernels.boundary_fill). The work buffers — a blocked
    map and a stack of 2 entries per pixel, about 14 MB on the T5688 — are allocated once
    per area size and reused by every later fill, which the kernel fully re-initialises."""
    h, w = pix.shape
    with _FILL_LOCK:
        work = _FILL_WORK.get((h, w))
        if work is None:
            # each pixel is pushed at most twice (from the rows above and below)
            work = (np.empty((h, w), dtype=np.uint8), np.empty(2 * h * w + 16, dtype=np.int32))
            _FILL_WORK[(h, w)] = work
        return _kernels().boundary_fill(pix, int(sx), int(sy), int(colour), int(wm), int(boundary),
                              int(rmask), work[0], work[1])


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
