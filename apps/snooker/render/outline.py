"""Polygon outlines in whole pixels for the Sigma (thesis 6.4.1): vertices rounded to the
pixels that hold them, edges as Bresenham (1965) draws them, and the Pitteway & Watkinson
coverage of each edge pixel by the polygon."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.render import kernels as K


def clip_to_screen(xy: np.ndarray, width: int, height: int) -> np.ndarray:
    """Sutherland-Hodgman clip of a screen polygon to the pixel centres' box
    [0.5, width - 0.5] x [0.5, height - 0.5], so its vertices round into the screen."""
    pts = [p for p in np.asarray(xy, dtype=np.float64)]
    for axis, lim, keep_below in ((0, 0.5, False), (0, width - 0.5, True),
                                  (1, 0.5, False), (1, height - 0.5, True)):
        res = []
        for k, p in enumerate(pts):
            q = pts[(k + 1) % len(pts)]
            pin = p[axis] <= lim if keep_below else p[axis] >= lim
            qin = q[axis] <= lim if keep_below else q[axis] >= lim
            if pin:
                res.append(p)
            if pin != qin:
                res.append(p + (lim - p[axis]) / (q[axis] - p[axis]) * (q - p))
        pts = res
        if not pts:
            return np.zeros((0, 2))
    return np.array(pts)


def pixel_vertices(xy: np.ndarray) -> np.ndarray:
    """(k, 2) screen points -> (m, 2) int64 pixels holding them, consecutive repeats dropped."""
    v = np.floor(xy).astype(np.int64).reshape(-1, 2)
    if len(v) == 0:
        return v
    keep = [0] + [k for k in range(1, len(v)) if not np.array_equal(v[k], v[k - 1])]
    v = v[keep]
    if len(v) > 1 and np.array_equal(v[0], v[-1]):
        v = v[:-1]
    return v


def bresenham(x0: int, y0: int, x1: int, y1: int) -> np.ndarray:
    """(n, 2) pixels of Bresenham's line from (x0, y0) to (x1, y1), both ends included: on
    the major axis every pixel, on the minor axis the nearest (halves away from the start)."""
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy))
    if n == 0:
        return np.array([[x0, y0]], dtype=np.int64)
    i = np.arange(n + 1, dtype=np.int64)
    if abs(dx) >= abs(dy):
        minor = (2 * i * abs(dy) + n) // (2 * n)
        return np.stack([x0 + np.sign(dx) * i, y0 + np.sign(dy) * minor], axis=1)
    minor = (2 * i * abs(dx) + n) // (2 * n)
    return np.stack([x0 + np.sign(dx) * minor, y0 + np.sign(dy) * i], axis=1)


FRACTION_BITS = 12  # the firmware vector's fixed point (docs/fidelity/sigma.md, reconstructed)


def firmware_line(x0: int, y0: int, x1: int, y1: int) -> np.ndarray:
    """(n, 2) pixels the Sigma's firmware sets for a vector (its 12-bit fixed-point DDA, as
    docs/fidelity/sigma.md describes it): the major axis one pixel a step, the minor axis
    the integer part of 1/2 plus the step times the slope truncated to 1/4096."""
    dx, dy = x1 - x0, y1 - y0
    sx, sy = (1 if dx >= 0 else -1), (1 if dy >= 0 else -1)
    adx, ady = abs(dx), abs(dy)
    i = np.arange(max(adx, ady) + 1, dtype=np.int64)
    half = 1 << (FRACTION_BITS - 1)
    if adx >= ady:
        slope = (ady << FRACTION_BITS) // adx if adx else 0
        return np.stack([x0 + sx * i, y0 + sy * ((half + i * slope) >> FRACTION_BITS)], 1)
    slope = (adx << FRACTION_BITS) // ady
    return np.stack([x0 + sx * ((half + i * slope) >> FRACTION_BITS), y0 + sy * i], 1)


def firmware_outline(v: np.ndarray, height: int) -> np.ndarray:
    """The pixels (x, row) the firmware sets for the closed polyline through ``v`` (x, row),
    sent in device coordinates (y up) vertex by vertex and back to the first."""
    dev = [(int(x), height - 1 - int(y)) for x, y in v]
    parts = [firmware_line(*dev[k], *dev[(k + 1) % len(dev)]) for k in range(len(dev))]
    pts = np.concatenate(parts)
    pts[:, 1] = height - 1 - pts[:, 1]
    return np.unique(pts, axis=0)


def outline_pixels(v: np.ndarray) -> np.ndarray:
    """Every pixel of the closed outline through integer vertices (duplicates removed)."""
    parts = [bresenham(*v[k], *v[(k + 1) % len(v)]) for k in range(len(v))]
    pts = np.concatenate(parts)
    return np.unique(pts, axis=0)


def signed_area(v: np.ndarray) -> float:
    a = np.asarray(v, dtype=np.float64)
    return 0.5 * float(np.sum(a[:, 0] * np.roll(a[:, 1], -1) - np.roll(a[:, 0], -1) * a[:, 1]))


def coverage(v: np.ndarray, pixels: np.ndarray) -> np.ndarray:
    """PW coverage of each pixel (x, y) by the polygon through the centres of the integer
    vertices ``v``: along each edge the pixel Bresenham's line picks is the one the edge
    crosses, so the anti-aliased boundary is exactly the outline (nothing beyond it)."""
    verts = np.ascontiguousarray(v + 0.5, dtype=np.float64)
    area = signed_area(verts)
    if abs(area) < 1e-12:
        return np.zeros(len(pixels))
    orient = 1.0 if area > 0 else -1.0
    return np.array([K.coverage_at(verts, orient, x + 0.5, y + 0.5) for x, y in pixels])
