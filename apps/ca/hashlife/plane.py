"""The 65536-square plane's two edges as HashLife frames (exact, not an infinite plane's).

Stepping needs a node twice the plane's size whose centre is the plane:

* wrapping edges: the torus tiled, i.e. four copies of the plane rolled by half its side
  (each quadrant of the frame then shows the plane as seen across the seam);
* bounded edges: the plane surrounded by ``WALL`` cells, which send nothing and never change,
  so no message crosses the edge and nothing is born outside it.

Either way the result of the frame after 2**j generations is exactly the plane after them.
"""

from __future__ import annotations

from apps.ca.hashlife.store import NodeStore


def frame(store: NodeStore, plane: int, edges: str) -> int:
    """The level-17 node whose centre is the level-16 ``plane`` on a plane with ``edges``."""
    nw, ne, sw, se = store.quadrants(plane)
    if edges == "wrap":
        rolled = store.join(se, sw, ne, nw)
        return store.join(rolled, rolled, rolled, rolled)
    w = int(store.wall[15])
    return store.join(store.join(w, w, w, nw), store.join(w, w, ne, w),
                      store.join(w, sw, w, w), store.join(se, w, w, w))
