"""Display primitives, their Sigma bytes, and the incremental redraw over the line.

A program describes its whole screen as an ordered list of primitives (later ones on top).
``Painter.update`` compares that list with what the terminal already shows and sends only
the difference: new primitives are drawn; a removed one is erased by a solid block of the
background over its bounding box, and every primitive that box touches is drawn again, in
order, with every later primitive that overlaps something redrawn (so the result is exactly
what a full redraw would show).  A polyline that only grew (freehand drawing) sends just
its new segments.  Vectors go in abbreviated mode (about half the characters, §3.1.4).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from camlab88.apps.kas.program.layout import BG, CHAR_H, CHAR_W, SCREEN_H, SCREEN_W
from camlab88.protocols.sigma import Encoder

Box = tuple[int, int, int, int]  # x0, y0, x1, y1 inclusive


@dataclass(frozen=True)
class Prim:
    """kind: "poly" (data = x0, y0, x1, y1, ...), "rect"/"block" (x0, y0, x1, y1; outline /
    solid), "text" (x, y) with ``text``."""

    kind: str
    colour: int
    data: tuple[int, ...]
    text: str = ""
    box: Box = field(init=False, compare=False, hash=False)

    def __post_init__(self) -> None:
        d = self.data
        if self.kind == "text":
            b = (d[0], d[1], d[0] + CHAR_W * len(self.text), d[1] + CHAR_H)
        else:
            xs, ys = d[0::2], d[1::2]
            b = (min(xs), min(ys), max(xs), max(ys))
        object.__setattr__(self, "box", b)


def poly(colour: int, pts: Sequence[tuple[int, int]] | np.ndarray) -> Prim:
    flat: list[int] = []
    last = None
    for x, y in pts:
        p = (int(x), int(y))
        if p != last:
            flat += p
            last = p
    return Prim("poly", colour, tuple(flat))


def rect(colour: int, x0: int, y0: int, x1: int, y1: int, solid: bool = False) -> Prim:
    return Prim("block" if solid else "rect", colour, (int(x0), int(y0), int(x1), int(y1)))


def text(colour: int, x: int, y: int, s: str) -> Prim:
    s = "".join(ch if 0x20 <= ord(ch) <= 0x7E else "?" for ch in s)
    return Prim("text", colour, (int(x), int(y)), s)


def encode(enc: Encoder, p: Prim) -> bytes:
    """The Sigma bytes that draw one primitive (colour set each time: primitives may be
    redrawn in any combination)."""
    d = p.data
    out = bytearray(enc.colour(p.colour))
    if p.kind == "poly":
        pts = list(zip(d[0::2], d[1::2], strict=True))
        if len(pts) == 1:
            pts = pts * 2  # a dot: a vector of length 0
        out += enc.abbreviated_polyline(pts)
    elif p.kind in ("rect", "block"):
        out += enc.move(d[0], d[1]) + enc.block(d[2], d[3], solid=p.kind == "block")
    elif p.kind == "text":
        if p.text:
            out += enc.move(d[0], d[1]) + enc.text(p.text)
    else:
        raise ValueError(f"unknown primitive kind {p.kind!r}")
    return bytes(out)


def _overlap(a: Box, b: Box) -> bool:
    return a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3]


def _grow(b: Box, m: int = 1) -> Box:
    return (max(b[0] - m, 0), max(b[1] - m, 0), min(b[2] + m, SCREEN_W - 1),
            min(b[3] + m, SCREEN_H - 1))


class Painter:
    """Keeps what the terminal shows (``shown``) and turns a new screen into the bytes that
    change it."""

    def __init__(self, enc: Encoder | None = None) -> None:
        self.enc = enc or Encoder()
        self.shown: list[Prim] = []
        self.stats = Counter[str]()

    def full(self, prims: list[Prim]) -> bytes:
        """Erase the planes and draw everything."""
        self.shown = list(prims)
        self.stats["full"] += 1
        return self.enc.erase() + b"".join(encode(self.enc, p) for p in prims)

    def update(self, prims: list[Prim]) -> bytes:
        old = Counter(self.shown)
        new = Counter(prims)
        removed = list((old - new).elements())
        added = set((new - old).elements())
        if not removed and not added:
            return b""
        # freehand: a removed polyline that is a prefix of an added one only grows
        grown: dict[Prim, int] = {}
        for r in list(removed):
            if r.kind != "poly":
                continue
            for a in added:
                if (a.kind == "poly" and a.colour == r.colour and a not in grown
                        and len(a.data) > len(r.data) and a.data[:len(r.data)] == r.data):
                    grown[a] = len(r.data) - 2
                    removed.remove(r)
                    break
        damage = [_grow(r.box) for r in removed]
        redraw: list[int] = []
        boxes: list[Box] = []
        for i, p in enumerate(prims):
            hit = p in added or any(_overlap(p.box, d) for d in damage) or \
                any(_overlap(p.box, b) for b in boxes)
            if hit:
                redraw.append(i)
                boxes.append(_grow(p.box))
        out = bytearray()
        for d in damage:
            out += self.enc.colour(BG) + self.enc.move(d[0], d[1]) + \
                self.enc.block(d[2], d[3], solid=True)
        for i in redraw:
            p = prims[i]
            start = grown.get(p)
            # a grown polyline touched by nothing else needs only its new segments
            if start is not None and not any(_overlap(p.box, d) for d in damage):
                p = Prim("poly", p.colour, p.data[start:])
                self.stats["grown"] += 1
            out += encode(self.enc, p)
        self.stats["erased"] += len(damage)
        self.stats["drawn"] += len(redraw)
        self.shown = list(prims)
        return bytes(out)


def clip_polyline(pts: np.ndarray, x0: float, y0: float, x1: float, y1: float
                  ) -> list[np.ndarray]:
    """Pieces of a polyline (float pixels) inside the rectangle (Liang-Barsky per segment)."""
    pts = np.asarray(pts, dtype=np.float64).reshape(-1, 2)
    inside = (pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1)
    if inside.all():
        return [pts]
    if len(pts) == 1:
        return []
    pieces: list[np.ndarray] = []
    cur: list[tuple[float, float]] = []
    for i in range(len(pts) - 1):
        ax, ay = pts[i]
        bx, by = pts[i + 1]
        dx, dy = bx - ax, by - ay
        t0, t1 = 0.0, 1.0
        ok = True
        for p, q in ((-dx, ax - x0), (dx, x1 - ax), (-dy, ay - y0), (dy, y1 - ay)):
            if abs(p) < 1e-9:  # parallel to this edge (or a dot): no division
                if q < 0:
                    ok = False
                    break
                continue
            r = q / p
            if p < 0:
                t0 = max(t0, r)
            else:
                t1 = min(t1, r)
        if not ok or t0 > t1:
            if cur:
                pieces.append(np.array(cur))
                cur = []
            continue
        a = (ax + t0 * dx, ay + t0 * dy)
        b = (ax + t1 * dx, ay + t1 * dy)
        if not cur or t0 > 0:
            if cur:
                pieces.append(np.array(cur))
            cur = [a]
        cur.append(b)
        if t1 < 1:
            pieces.append(np.array(cur))
            cur = []
    if cur:
        pieces.append(np.array(cur))
    return pieces


def chain_prims(points_px: np.ndarray, colours: Sequence[int], clip: Box,
                colour_of=lambda c: c) -> list[Prim]:
    """A line-chain (float pixels, per-point colours: the colour of the segment drawn *to*
    the point) as polylines of one colour each, clipped to ``clip``."""
    pts = np.asarray(points_px, dtype=np.float64).reshape(-1, 2)
    cols = [colour_of(int(c)) for c in colours]
    out: list[Prim] = []
    if len(pts) == 0:
        return out
    if len(pts) == 1:
        runs = [(cols[0], pts)]
    else:
        runs = []
        start = 1
        for i in range(2, len(pts) + 1):
            if i == len(pts) or cols[i] != cols[start]:
                runs.append((cols[start], pts[start - 1:i]))
                start = i
    for c, seg in runs:
        for piece in clip_polyline(seg, *clip):
            out.append(poly(c, np.rint(piece).astype(int)))
    return out
