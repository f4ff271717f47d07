"""The Sigma host program's own raster loops (numba; one signature each): the boundary fill
it expects the terminal to perform, simulated on its copy of the screen."""

from __future__ import annotations

from numba import njit


@njit(cache=True, nogil=True)
def fill4(idx, sx, sy, colour, stack):  # numba kernel
    """Flood fill 4-connected from (sx, sy) over pixels whose index is not ``colour``,
    setting them to it (the firmware fill with boundary = fill colour, thesis 6.4.1).
    Returns the number of pixels set. ``stack`` needs 2 entries per pixel."""
    h = idx.shape[0]
    w = idx.shape[1]
    if idx[sy, sx] == colour:
        return 0
    top = 0
    stack[top] = sy * w + sx
    top += 1
    count = 0
    while top > 0:
        top -= 1
        y = stack[top] // w
        x = stack[top] - y * w
        if idx[y, x] == colour:
            continue
        xl = x
        while xl > 0 and idx[y, xl - 1] != colour:
            xl -= 1
        xr = x
        while xr < w - 1 and idx[y, xr + 1] != colour:
            xr += 1
        for xi in range(xl, xr + 1):
            idx[y, xi] = colour
        count += xr - xl + 1
        for ny in (y - 1, y + 1):
            if ny < 0 or ny >= h:
                continue
            inrun = False
            for xi in range(xl, xr + 1):
                if idx[ny, xi] == colour:
                    inrun = False
                elif not inrun:
                    if top < stack.shape[0]:
                        stack[top] = ny * w + xi
                        top += 1
                    inrun = True
    return count
