"""The 65536-square plane's two edges as frames of the binary path (see ../plane.py): the
torus tiled for wrapping edges, the plane inside all-wall leaves for bounded ones."""

from __future__ import annotations

from apps.ca.hashlife.bits.store import HAS_WALL, BitStore

PLANE_LEVEL = 16


def frame(store: BitStore, plane: int, edges: str) -> int:
    """The level-17 node whose centre is the level-16 ``plane`` on a plane with ``edges``."""
    nw, ne, sw, se = store.quadrants(plane)
    k = PLANE_LEVEL
    if edges == "wrap":
        rolled = store.join(se, sw, ne, nw, k)
        return store.join(rolled, rolled, rolled, rolled, k + 1)
    store.meta[HAS_WALL] = 1
    w = int(store.wall[k - 1])
    return store.join(store.join(w, w, w, nw, k), store.join(w, w, ne, w, k),
                      store.join(w, sw, w, w, k), store.join(se, w, w, w, k), k + 1)
