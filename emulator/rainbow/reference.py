"""A straightforward per-pixel compositor of the model, for checking the compiler.

It walks the graph itself (sharing no code with the compiler or the video processor) and,
instance by instance, keeps for every screen pixel the greatest priority key seen so far,
the OR of the words of the instances holding that key, and the largest LUT page among them.
"""

from __future__ import annotations

import numpy as np

from emulator.rainbow.graph import SCREEN, SCREEN_H, SCREEN_W, Cluster, Pad, PadGraph


def _walk(graph: PadGraph):
    def rec(nid, ox, oy, clip, key):
        node = graph.nodes[nid]
        if isinstance(node, Pad):
            yield key, node, ox, oy, clip
            return
        assert isinstance(node, Cluster)
        if nid != SCREEN:
            clip = (max(clip[0], ox), max(clip[1], oy),
                    min(clip[2], ox + node.width), min(clip[3], oy + node.height))
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
