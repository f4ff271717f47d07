"""Cells to a level-16 tree of the 65536-square plane and back."""

from __future__ import annotations

import numpy as np
from numba import njit

from apps.ca.hashlife.store import WALL, join

PLANE_LEVEL = 16


@njit(cache=True)
def _morton(xs, ys):
    """Interleaved bits (x in the even bits): sorting by it groups every quadtree square."""
    keys = np.empty(xs.shape[0], np.int64)
    for i in range(xs.shape[0]):
        x, y, m = xs[i], ys[i], np.int64(0)
        for bit in range(PLANE_LEVEL):
            m |= ((x >> bit) & 1) << (2 * bit)
            m |= ((y >> bit) & 1) << (2 * bit + 1)
        keys[i] = m
    return keys


@njit(cache=True)
def build(keys, values, nodes, slots, meta, empty):
    """The plane's node from cells sorted by Morton key (distinct keys, values > 0): each
    level groups runs of equal key >> 2 into a parent, absent quadrants empty; -1 if full."""
    n = keys.shape[0]
    if n == 0:
        return np.int64(empty[PLANE_LEVEL])
    keys = keys.copy()
    ids = values.copy()
    for level in range(PLANE_LEVEL):
        quads = np.empty(4, np.int64)
        m = 0
        i = 0
        while i < n:
            parent = keys[i] >> 2
            quads[:] = empty[level]
            while i < n and keys[i] >> 2 == parent:
                quads[keys[i] & 3] = ids[i]
                i += 1
            node = join(quads[0], quads[1], quads[2], quads[3], nodes, slots, meta)
            if node < 0:
                return np.int64(-1)
            keys[m] = parent
            ids[m] = node
            m += 1
        n = m
    return np.int64(ids[0])


@njit(cache=True)
def _count(node, level, nodes, empty):
    if level == 0:
        return np.int64(1 if 0 < node < WALL else 0)
    if node == empty[level]:
        return np.int64(0)
    total = np.int64(0)
    for q in range(4):
        total += _count(np.int64(nodes[node, q]), level - 1, nodes, empty)
    return total


@njit(cache=True)
def _emit(node, level, y0, x0, nodes, empty, out, n):
    """Append (y, x, value) of the live cells of ``node`` to ``out`` from row ``n``."""
    if level == 0:
        if 0 < node < WALL:
            out[n, 0], out[n, 1], out[n, 2] = y0, x0, node
            return n + 1
        return n
    if node == empty[level]:
        return n
    h = np.int64(1) << (level - 1)
    k = level - 1
    n = _emit(np.int64(nodes[node, 0]), k, y0, x0, nodes, empty, out, n)
    n = _emit(np.int64(nodes[node, 1]), k, y0, x0 + h, nodes, empty, out, n)
    n = _emit(np.int64(nodes[node, 2]), k, y0 + h, x0, nodes, empty, out, n)
    return _emit(np.int64(nodes[node, 3]), k, y0 + h, x0 + h, nodes, empty, out, n)


@njit(cache=True)
def _cells(node, nodes, empty):
    top = np.int64(PLANE_LEVEL)
    out = np.empty((_count(node, top, nodes, empty), 3), np.int64)
    _emit(node, top, np.int64(0), np.int64(0), nodes, empty, out, np.int64(0))
    return out


def cells(node: int, nodes: np.ndarray, empty: np.ndarray) -> np.ndarray:
    """(y, x, value) rows of the plane node's live cells, sorted row by row (by numpy:
    a sort inside a kernel compiles numba's quicksort, seconds of a first run)."""
    out = _cells(np.int64(node), nodes, empty)
    return out[np.argsort(out[:, 0] * (1 << PLANE_LEVEL) + out[:, 1])]


@njit(cache=True)
def any_live(node, level, y0, x0, top, bottom, left, right, nodes, empty):
    """Whether ``node`` (its corner at y0, x0) has a live cell in rows top..bottom-1,
    columns left..right-1."""
    side = np.int64(1) << level
    if (node == empty[level] or y0 >= bottom or y0 + side <= top or x0 >= right
            or x0 + side <= left):
        return False
    if level == 0:
        return 0 < node < WALL
    h = side >> 1
    k = level - 1
    return (any_live(np.int64(nodes[node, 0]), k, y0, x0, top, bottom, left, right, nodes, empty)
            or any_live(np.int64(nodes[node, 1]), k, y0, x0 + h, top, bottom, left, right, nodes,
                        empty)
            or any_live(np.int64(nodes[node, 2]), k, y0 + h, x0, top, bottom, left, right, nodes,
                        empty)
            or any_live(np.int64(nodes[node, 3]), k, y0 + h, x0 + h, top, bottom, left, right,
                        nodes, empty))


def near_seam(node: int, distance: int, nodes: np.ndarray, empty: np.ndarray) -> bool:
    """Whether the plane ``node`` has a live cell within ``distance`` of the wrapping
    plane's seam (the first or last ``distance`` rows or columns)."""
    side = 1 << PLANE_LEVEL
    d = min(int(distance), side)
    strips = ((0, d, 0, side), (side - d, side, 0, side), (0, side, 0, d),
              (0, side, side - d, side))
    return any(any_live(np.int64(node), np.int64(PLANE_LEVEL), np.int64(0), np.int64(0),
                        *(np.int64(v) for v in strip), nodes, empty) for strip in strips)


def morton(xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    return _morton(np.ascontiguousarray(xs, np.int64), np.ascontiguousarray(ys, np.int64))
