"""The 65536-square plane's two edges as HashLife frames (exact, not an infinite plane's).

Stepping needs a node twice the plane's size whose centre is the plane:

* wrapping edges: the torus tiled, i.e. four copies of the plane rolled by half its side
  (each quadrant of the frame then shows the plane as seen across the seam);
* bounded edges: the plane surrounded by ``WALL`` cells, which send nothing and never change,
  so no message crosses the edge and nothing is born outside it.

Either way the result of the frame after any number of generations is exactly the plane after them.
One frame for both kinds of leaf: the level is part of a node's key.
"""

from __future__ import annotations

PLANE_LEVEL = 16


def frame(store, plane: int, edges: str) -> int:
    """The level-17 node whose centre is the level-16 ``plane`` on a plane with ``edges``
    (``store``: the rule set's ``Store``, either kind of leaf)."""
    nw, ne, sw, se = store.quadrants(plane)
    k = PLANE_LEVEL
    if edges == "wrap":
        rolled = store.join(se, sw, ne, nw, k)
        return store.join(rolled, rolled, rolled, rolled, k + 1)
    store.mark_wall()
    w = int(store.wall[k - 1])
    return store.join(store.join(w, w, w, nw, k), store.join(w, w, ne, w, k),
                      store.join(w, sw, w, w, k), store.join(se, w, w, w, k), k + 1)
