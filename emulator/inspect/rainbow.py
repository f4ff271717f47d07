"""The Rainbow inspector panel: the band structure of the current frame drawn as bands over
the screen, video memory use per plane, and the pad graph as a tree (clusters, pads, and
the arcs between them with their offsets, priorities and on/off)."""

from __future__ import annotations

from typing import Any

import numpy as np

from camlab88.emulator.inspect import draw

BAND_COLOURS = [(255, 200, 60), (80, 200, 255)]
TREE_DEPTH = 8


class RainbowPanel:
    def __init__(self, device: Any, width: int) -> None:
        self.device, self.width = device, width

    def __call__(self, frame: np.ndarray) -> np.ndarray:
        img = draw.canvas(self.width, frame.shape[0])
        d = self.device
        draw.text(img, 6, 4, f"RAINBOW   frame {d.frame_count}   t {d.time_ms / 1000:.2f} s",
                  draw.ACCENT)
        y = self._bands(img, frame, 18)
        y = self._memory(img, y + 4)
        self._tree(img, y + 4)
        return img

    def _bands(self, img: np.ndarray, frame: np.ndarray, y: int) -> int:
        """The screen at the panel's width, darkened, each band outlined, spans ticked."""
        structure = self.device.bands()
        h, w = frame.shape[:2]
        sw = self.width - 12
        sh = h * sw // w
        ys = np.arange(sh) * h // sh
        xs = np.arange(sw) * w // sw
        view = img[y + 12:y + 12 + sh, 6:6 + sw]
        view[:] = (frame[np.ix_(ys, xs)] // 3)
        n_spans = len(structure.spans)
        draw.text(img, 6, y, f"bands: {len(structure)}  spans: {n_spans}  sources: "
                  f"{len(structure.sources)}", draw.ACCENT)
        for i, (y0, y1, s0, s1) in enumerate(structure.bands.tolist()):
            colour = BAND_COLOURS[i % 2]
            top, bottom = y0 * sh // h, max(y0 * sh // h + 1, y1 * sh // h)
            draw.frame_box(view, 0, top, sw, bottom - top, colour)
            for x0, _x1, _page, r0, r1 in structure.spans[s0:s1].tolist():
                if x0 > 0:
                    draw.fill(view, x0 * sw // w, top, 1, bottom - top, colour)
                if r1 > r0 and bottom - top > 10:
                    draw.text(view, x0 * sw // w + 2, top + 1, str(r1 - r0), colour)
        return y + 12 + sh

    def _memory(self, img: np.ndarray, y: int) -> int:
        mem = self.device.memory
        used = mem._used  # per granule: which planes are taken
        draw.text(img, 6, y, f"video memory {mem.width}x{mem.height} x 8 planes "
                  f"({mem.words_16bit} 16-bit words)", draw.ACCENT)
        y += 12
        bar_w = self.width - 12 - 90
        for p in range(8):
            share = float(((used >> p) & 1).mean())
            draw.text(img, 6, y, f"plane {p} {100 * share:3.0f}%")
            draw.frame_box(img, 90, y + 1, bar_w, 8, draw.DIM)
            draw.fill(img, 91, y + 2, int((bar_w - 2) * share), 6, draw.ACCENT)
            y += 10
        return y

    def _tree(self, img: np.ndarray, y: int) -> None:
        _, ch = draw.cell()
        lines = tree_lines(self.device.graph)
        room = (img.shape[0] - y - 12) // ch
        draw.text(img, 6, y, f"pad graph ({len(self.device.graph.nodes)} nodes, "
                  f"{len(self.device.graph.arcs)} arcs)", draw.ACCENT)
        shown = lines if len(lines) <= room else [*lines[:room - 1],
                                                  f"... {len(lines) - room + 1} more"]
        for i, line in enumerate(shown):
            draw.text(img, 6, y + 12 + i * ch, line[: self.width // 6 - 2])


def node_text(graph: Any, nid: int) -> str:
    from camlab88.emulator.rainbow.graph import Cluster

    n = graph.nodes[nid]
    if isinstance(n, Cluster):
        return f"cluster {nid} {n.width}x{n.height}" if nid else "screen 768x576"
    return f"pad {nid} {n.width}x{n.height} d{n.depth} pl{n.plane} pg{n.lut_page}"


def tree_lines(graph: Any) -> list[str]:
    """The graph from the screen down: one line a node, arcs as ``+x,+y p0`` before it; a
    node met again is named, not expanded (nodes may be mapped many times)."""
    from camlab88.emulator.rainbow.graph import SCREEN, Cluster

    lines, seen = [node_text(graph, SCREEN)], {SCREEN}

    def walk(nid: int, depth: int) -> None:
        node = graph.nodes[nid]
        if not isinstance(node, Cluster) or depth > TREE_DEPTH:
            return
        for aid in node.arcs:
            a = graph.arcs[aid]
            again = a.child in seen
            seen.add(a.child)
            lines.append(f"{'  ' * depth}a{aid} {a.x:+d},{a.y:+d} p{a.priority}"
                         f"{'' if a.on else ' off'} > {node_text(graph, a.child)}"
                         f"{' (again)' if again else ''}")
            if not again:
                walk(a.child, depth + 1)
    walk(SCREEN, 1)
    loose = sorted(set(graph.nodes) - seen)
    if loose:
        lines.append(f"unmapped: {', '.join(node_text(graph, n) for n in loose[:6])}"
                     f"{' ...' if len(loose) > 6 else ''}")
    return lines
