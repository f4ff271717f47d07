"""A straightforward per-pixel compositor of the model, for checking the compiler.

It walks the graph itself (sharing no code with the compiler or the video processor) and,
instance by instance, keeps for every screen pixel the greatest priority key seen so far,
the OR of the words of the instances holding that key, and the largest LUT page among them.
"""

from __future__ import annotations

import numpy as np

from camlab88.emulator.rainbow.errors import GraphError
from camlab88.emulator.rainbow.graph import (
    MAX_INSTANCES,
    MAX_VISITS,
    SCREEN,
    SCREEN_H,
    SCREEN_W,
    Cluster,
    Pad,
    PadGraph,
)


def _walk(graph: PadGraph):
    # The same work limits as PadGraph.instances, counted independently: a graph the
    # compiler refuses is refused here too, instead of taking minutes.
    count = {"visits": 0, "instances": 0}

    def rec(nid, ox, oy, clip, key):
        count["visits"] += 1
        if count["visits"] > MAX_VISITS:
            raise GraphError(f"the graph has more than {MAX_VISITS} paths from the screen")
        node = graph.nodes[nid]
        if isinstance(node, Pad):
            if (max(clip[0], ox) < min(clip[2], ox + node.width)
                    and max(clip[1], oy) < min(clip[3], oy + node.height)):
                count["instances"] += 1
                if count["instances"] > MAX_INSTANCES:
                    raise GraphError(f"the graph maps pads more than {MAX_INSTANCES} times")
            yield key, node, ox, oy, clip
            return
        assert isinstance(node, Cluster)
        if nid != SCREEN:
            clip = (max(clip[0], ox), max(clip[1], oy),
                    min(clip[2], ox + node.width), min(clip[3], oy + node.height))
        if clip[0] >= clip[2] or clip[1] >= clip[3]:
            return  # nothing below a fully clipped cluster can show
        for aid in node.arcs:
            a = graph.arcs[aid]
            if a.on:
                yield from rec(a.child, ox + a.x, oy + a.y, clip, key + (a.priority,))

    yield from rec(SCREEN, 0, 0, (0, 0, SCREEN_W, SCREEN_H), ())


def reference_frame(graph: PadGraph, words: np.ndarray, lut: np.ndarray) -> np.ndarray:
    found = list(_walk(graph))
    ranks = {k: n for n, k in enumerate(sorted({f[0] for f in found}))}
    best = np.full((SCREEN_H, SCREEN_W), -1, np.int64)
    word = np.zeros((SCREEN_H, SCREEN_W), np.int64)
    page = np.zeros((SCREEN_H, SCREEN_W), np.int64)
    for key, pad, ox, oy, clip in found:
        x0, y0 = max(clip[0], ox), max(clip[1], oy)
        x1, y1 = min(clip[2], ox + pad.width), min(clip[3], oy + pad.height)
        if x0 >= x1 or y0 >= y1:
            continue
        if pad.depth:
            a = pad.alloc
            v = words[a.y + y0 - oy: a.y + y1 - oy, a.x + x0 - ox: a.x + x1 - ox].astype(np.int64)
            v &= ((1 << pad.depth) - 1) << pad.plane
        else:
            v = np.zeros((y1 - y0, x1 - x0), np.int64)
        r = ranks[key]
        b = best[y0:y1, x0:x1]
        gt, eq = r > b, r == b
        w = word[y0:y1, x0:x1]
        p = page[y0:y1, x0:x1]
        word[y0:y1, x0:x1] = np.where(gt, v, np.where(eq, w | v, w))
        tied_page = np.maximum(p, pad.lut_page)
        page[y0:y1, x0:x1] = np.where(gt, pad.lut_page, np.where(eq, tied_page, p))
        best[y0:y1, x0:x1] = np.maximum(b, r)
    return lut[page * 256 + word]
