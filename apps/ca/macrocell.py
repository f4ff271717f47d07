"""Golly's macrocell format (``.mc``): a pattern as the nodes of its quadtree, children first.

The first line is ``[M2] ...``; ``#R rule``, ``#G generation``, ``#C``/``#N`` comment lines
may follow. Each further line is one node, numbered from 1:

* ``$``-separated rows of ``.`` and ``*`` (trailing dots and empty rows left out): an 8 x 8
  leaf of a two-state pattern (level 3);
* ``1 a b c d``: a 2 x 2 node of states a (north-west), b (north-east), c, d (multi-state);
* ``L a b c d`` with L >= 2: a node of side 2**L whose quadrants are the nodes numbered a..d
  (0 = empty), each of level L - 1.

The last node is the whole pattern around Golly's origin, which becomes the pattern's
reference point: the root of level L has its top-left cell at (-2**(L-1), 1 - 2**(L-1))
(Golly's trees count rows upwards, cell (x, y) at tree row -1 - y; checked with bgolly,
whose RLE of a file puts the same cells where our reader of its .mc does).
A file can describe more cells than memory holds in a few lines, so the population and
bounding box are worked out on the nodes first, and a pattern wider than the plane or with
more than MAX_CELLS cells is refused before any cell is listed.
"""

from __future__ import annotations

import re

import numpy as np

from camlab88.base import budget

MAX_LEVEL = 62  # 2**62: coordinates still fit an int64
MAX_CELLS = 1 << 22  # cells of a sparse pattern listed at most (~0.1 GB as cell arrays)
MAX_GRID = 1 << 28  # bytes of a dense pattern's grid at most (painted, never listed)
GRID_FILL = 16  # as rle_body.GRID_FILL: a grid from 1/16 full
_QUAD = ((0, 0), (1, 0), (0, 1), (1, 1))  # (x, y) of quadrants nw, ne, sw, se
# What reading costs, measured (1e6 node lines, 3e5 leaves of 16 cells): a line ~260 bytes
# (its string, the node's Python values, then its row in the numpy arrays), a leaf's live
# cell ~24 (its offsets, listed once); a listed cell 24 bytes, three times over while sorted
LINE_BYTES = 260
LEAF_CELL_BYTES = 24
CELL_BYTES = 3 * 24
GRID_BYTES = 4  # as rle_body.GRID_BYTES: a grid cell held and run


class McError(ValueError):
    """A fault at (line, column) of a macrocell file."""

    def __init__(self, line: int, column: int, message: str) -> None:
        super().__init__(message)
        self.line, self.column = line, column


class _Tree:
    """The nodes read so far: level, quadrants (a level-1 node: its four states; an 8 x 8
    leaf: none, its cells in ``bits``) and population, as plain Python values while reading
    (numpy arrays of a handful of numbers cost more than the numbers); the boxes are worked
    out afterwards, all nodes of a level at once (``boxes``)."""

    def __init__(self) -> None:
        # index 0 is the empty node of every level
        self.level = [0]
        self.kids: list[tuple[int, ...]] = [(0, 0, 0, 0)]
        self.bits: list[int | None] = [None]  # an 8 x 8 leaf's cells, bit 8 y + x
        self.pop = [0]
        self.top = 0  # largest state

    def add_bitmap(self, bits: int, pop: int) -> None:
        self.level.append(3)
        self.kids.append((0, 0, 0, 0))
        self.bits.append(bits)
        self.pop.append(pop)
        if pop:
            self.top = max(self.top, 1)

    def add_states(self, states: tuple[int, ...]) -> None:
        """A level-1 node: the states of its cells nw, ne, sw, se."""
        self.level.append(1)
        self.kids.append(states)
        self.bits.append(None)
        self.pop.append(sum(1 for t in states if t))
        self.top = max(self.top, *states)

    def add_node(self, level: int, kids: tuple[int, ...]) -> None:
        self.level.append(level)
        self.kids.append(kids)
        self.bits.append(None)
        pop = self.pop
        self.pop.append(pop[kids[0]] + pop[kids[1]] + pop[kids[2]] + pop[kids[3]])


_ROW_BITS = str.maketrans(".*", "01")
_LEAF_ROW = re.compile(r"[.*]{0,8}")


def _bitmap(text: str, line: int, cache: dict) -> tuple[int, int]:
    """(cells as bits, population) of an 8 x 8 leaf written as rows of '.' and '*' each
    ended by '$' (identical leaves, common in a file, are decoded once)."""
    got = cache.get(text)
    if got is not None:
        return got
    rows = text.split("$")
    col = 1
    bits = 0
    for y, row in enumerate(rows[:-1] if rows[-1] == "" else rows):
        if y >= 8 or not _LEAF_ROW.fullmatch(row):
            bad = next((i for i, ch in enumerate(row) if ch not in ".*"), None)
            if y < 8 and bad is not None:
                raise McError(line, col + bad, f"expected '.', '*' or '$', found {row[bad]!r}")
            raise McError(line, col + (8 if y < 8 else 0), "a leaf is 8 cells wide and 8 tall")
        if row:
            bits |= int(row.translate(_ROW_BITS)[::-1], 2) << (8 * y)
        col += len(row) + 1
    got = (bits, bits.bit_count())
    cache[text] = got
    return got


# a node line as it always is: five numbers of at most ten digits (else _node_line says why)
_NODE = re.compile(r"([0-9]{1,10})\s+([0-9]{1,10})\s+([0-9]{1,10})\s+([0-9]{1,10})"
                   r"\s+([0-9]{1,10})")


def _node_line(tree: _Tree, text: str, line: int) -> None:
    m = _NODE.fullmatch(text)
    if m is not None:
        level = int(m[1])
        kids = (int(m[2]), int(m[3]), int(m[4]), int(m[5]))
        levels = tree.level
        if 2 <= level <= MAX_LEVEL and all(k < len(levels) and (not k or levels[k] == level - 1)
                                           for k in kids):
            tree.add_node(level, kids)
            return
    parts = text.split()
    if len(parts) != 5 or not all(p.isascii() and p.isdigit() and len(p) <= 10
                                  for p in parts):
        raise McError(line, 1, f"expected a node 'level a b c d' (five numbers) or a leaf "
                               f"of '.', '*' and '$', found {text[:40]!r}")
    level, *kids = (int(p) for p in parts)
    if not 1 <= level <= MAX_LEVEL:
        raise McError(line, 1, f"a node's level is 1..{MAX_LEVEL}, found {level}")
    if level == 1:
        bad = [k for k in kids if k > 255]
        if bad:
            raise McError(line, 1, f"a cell state is 0..255, found {bad[0]}")
        tree.add_states(tuple(kids))
        return
    levels = tree.level
    for k in kids:
        if k >= len(levels):
            raise McError(line, 1, f"node {k} is not defined before this line (nodes are "
                                   f"numbered from 1 in order; this is node {len(levels)})")
        if k and levels[k] != level - 1:
            raise McError(line, 1, f"node {k} has level {levels[k]}, a quadrant of a "
                                   f"level-{level} node needs level {level - 1}")
    tree.add_node(level, tuple(kids))


def read_tree(text: str, source: str = "<mc>") -> tuple[_Tree, str, list[str]]:
    """The nodes, the rule (``#R``) and the comments of a macrocell file (one over the
    memory budget is refused before its lines are split: base.budget)."""
    count = text.count("\n") + 1
    budget.check(source, len(text) + count * LINE_BYTES + text.count("*") * LEAF_CELL_BYTES,
                 f"reading its {count:,} lines")
    lines = text.splitlines()
    if not lines or not lines[0].startswith("[M2]"):
        raise McError(1, 1, "expected '[M2]' starting a macrocell file")
    tree, rule, comments = _Tree(), "", []
    leaves: dict = {}
    for n, raw in enumerate(lines[1:], start=2):
        s = raw.strip()
        if not s:
            continue
        if s.startswith("#"):
            if s[:2] == "#R":
                rule = s[2:].strip()
            elif s[:2] in ("#C", "#N"):
                comments.append(s[2:].strip())
            continue
        if s[0] in ".*$":
            tree.add_bitmap(*_bitmap(s, n, leaves))
        else:
            _node_line(tree, s, n)
    if len(tree.level) == 1:
        raise McError(max(1, len(lines)), 1, "expected at least one node, found none")
    return tree, rule, comments


# cells listed at once while a tree is expanded (the arrays of one batch: ~10 bytes a cell)
BATCH = 1 << 20
_QX = np.array([0, 1, 0, 1], np.int64)
_QY = np.array([0, 0, 1, 1], np.int64)


class _Nodes:
    """The tree as numpy arrays, for expanding many placed copies of nodes at once."""

    def __init__(self, tree: _Tree) -> None:
        self.level = np.array(tree.level, np.int64)
        self.kids = np.array(tree.kids, np.int64)  # a level-1 node's: its states
        # (a node beyond the cells a pattern may have is never expanded whole: it is split)
        self.pop = np.array([min(p, BATCH << 1) for p in tree.pop], np.int64)
        # each 8 x 8 leaf's cells, one after another: leaf k's from start[k], count[k] of them
        offsets = [[i for i in range(64) if b >> i & 1] if b is not None else []
                   for b in tree.bits]
        self.count = np.array([len(o) for o in offsets], np.int64)
        self.start = np.cumsum(self.count) - self.count
        flat = np.array([i for o in offsets for i in o], np.int64)
        self.offx, self.offy = flat & 7, flat >> 3
        self.is_bitmap = np.array([b is not None for b in tree.bits], np.bool_)

    def box(self, root: int) -> tuple[int, int, int, int] | None:
        """The live cells' box of node ``root`` relative to its top-left (None: empty),
        worked out for every node, bottom-up, all nodes of a level at once (a node's
        quadrants are one level below it)."""
        n = self.level.size
        far = np.int64(1) << np.int64(MAX_LEVEL)  # beyond any cell: an empty side
        lo = np.full((n, 2), far, np.int64)  # (x, y) of the top-left live cell
        hi = np.full((n, 2), -1, np.int64)  # (x, y) of the bottom-right one
        leaf = np.flatnonzero(self.is_bitmap & (self.count > 0))
        if leaf.size:
            starts = self.start[leaf]
            lo[leaf, 0] = np.minimum.reduceat(self.offx, starts)
            lo[leaf, 1] = np.minimum.reduceat(self.offy, starts)
            hi[leaf, 0] = np.maximum.reduceat(self.offx, starts)
            hi[leaf, 1] = np.maximum.reduceat(self.offy, starts)
        quad = np.stack([_QX, _QY], axis=1)  # (4, 2): offsets of the quadrants in halves
        for level in range(1, int(self.level.max()) + 1):
            ks = np.flatnonzero((self.level == level) & ~self.is_bitmap)
            if not ks.size:
                continue
            kids = self.kids[ks]
            if level == 1:  # quadrants are cells: live where the state is not 0
                live, klo, khi = kids != 0, quad[None], quad[None]
            else:
                live = hi[kids, 0] >= 0
                half = np.int64(1) << np.int64(level - 1)
                klo, khi = lo[kids] + quad * half, hi[kids] + quad * half
            lo[ks] = np.where(live[..., None], klo, far).min(axis=1)
            hi[ks] = np.where(live[..., None], khi, -1).max(axis=1)
        if hi[root, 0] < 0:
            return None
        return int(lo[root, 0]), int(lo[root, 1]), int(hi[root, 0]), int(hi[root, 1])

    def down(self, ks: np.ndarray, xs: np.ndarray, ys: np.ndarray, level: int
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The non-empty quadrants of nodes ``ks`` (of ``level``) placed at (xs, ys)."""
        half = np.int64(1) << np.int64(level - 1)
        kids = self.kids[ks]
        live = kids != 0
        return (kids[live], (xs[:, None] + _QX * half)[live],
                (ys[:, None] + _QY * half)[live])

    def cells(self, ks: np.ndarray, xs: np.ndarray, ys: np.ndarray, level: int
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Every cell of nodes ``ks`` (all of ``level``) placed at (xs, ys)."""
        out = []
        while ks.size:
            if level == 3:
                leaf = self.is_bitmap[ks]
                if leaf.any():
                    out.append(self._bitmap_cells(ks[leaf], xs[leaf], ys[leaf]))
                    ks, xs, ys = ks[~leaf], xs[~leaf], ys[~leaf]
            if level == 1:
                states = self.kids[ks]
                live = states != 0
                out.append(((xs[:, None] + _QX)[live], (ys[:, None] + _QY)[live],
                            states[live]))
                break
            ks, xs, ys = self.down(ks, xs, ys, level)
            level -= 1
        if len(out) == 1:
            return out[0]
        return tuple(np.concatenate([o[i] for o in out]) for i in range(3))

    def _bitmap_cells(self, ks: np.ndarray, xs: np.ndarray, ys: np.ndarray
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        count = self.count[ks]
        copy = np.repeat(np.arange(ks.size), count)
        first = np.cumsum(count) - count
        at = self.start[ks][copy] + np.arange(copy.size) - first[copy]
        return (xs[copy] + self.offx[at], ys[copy] + self.offy[at],
                np.ones(copy.size, np.int64))


def _pieces(nodes: _Nodes, root: int, x: int, y: int, emit) -> None:
    """``emit(xs, ys, ts)`` the cells of node ``root`` placed with its top-left at (x, y),
    at most about BATCH cells at a time."""
    todo = [(np.array([root], np.int64), np.array([x], np.int64), np.array([y], np.int64),
             int(nodes.level[root]))]
    while todo:
        ks, xs, ys, level = todo.pop()
        pops = nodes.pop[ks]
        total = int(pops.sum())
        if total > BATCH and ks.size > 1:  # two batches of about half the cells each
            cut = min(max(int(np.searchsorted(np.cumsum(pops), total // 2)), 1), ks.size - 1)
            todo.append((ks[cut:], xs[cut:], ys[cut:], level))
            todo.append((ks[:cut], xs[:cut], ys[:cut], level))
        elif total > BATCH and level > 1 and not nodes.is_bitmap[ks[0]]:
            todo.append((*nodes.down(ks, xs, ys, level), level - 1))  # one node: its quadrants
        elif total:
            emit(*nodes.cells(ks, xs, ys, level))


def cells_of(tree: _Tree, last_line: int, source: str = "<mc>"
             ) -> tuple[tuple[np.ndarray, np.ndarray, np.ndarray] | np.ndarray,
                        tuple[int, int]]:
    """The root's cells relative to its live box's top-left — as arrays, or a uint8 grid
    for a dense pattern — and Golly's origin in those coordinates (a pattern whose grid or
    cells would exceed the memory budget is refused before either is made)."""
    root = len(tree.level) - 1
    nodes = _Nodes(tree)
    level, box, pop = tree.level[root], nodes.box(root), tree.pop[root]
    half = 1 << (level - 1)
    if box is None:
        empty = np.zeros(0, np.int64)
        return (empty, empty, empty), (0, 0)
    x0, y0, x1, y1 = box
    w, h = x1 - x0 + 1, y1 - y0 + 1
    if w > 65536 or h > 65536:
        raise McError(last_line, 1, f"pattern is {w} x {h} cells, wider or taller than the "
                                    "65536-cell plane")
    grid = pop * GRID_FILL >= w * h and w * h <= MAX_GRID and tree.top <= 255
    if not grid and pop > MAX_CELLS:
        raise McError(last_line, 1, f"pattern has {pop} cells, more than {MAX_CELLS} can be "
                                    "loaded")
    origin = (half - x0, half - 1 - y0)
    batch = min(pop, BATCH << 1) * CELL_BYTES  # the cells of one expansion step
    if grid:
        budget.check(source, w * h * GRID_BYTES + batch, f"its {w:,} x {h:,} grid")
    else:
        budget.check(source, pop * CELL_BYTES, f"its {pop:,} live cells")
    if grid:
        g = np.zeros((h, w), np.uint8)

        def paint(xs: np.ndarray, ys: np.ndarray, ts: np.ndarray) -> None:
            g[ys, xs] = ts

        _pieces(nodes, root, -x0, -y0, paint)
        return g, origin
    pieces: list = []
    _pieces(nodes, root, -x0, -y0, lambda *piece: pieces.append(piece))
    xs, ys, ts = (np.concatenate([p[i] for p in pieces]) for i in range(3))
    order = np.lexsort((xs, ys))
    return (xs[order], ys[order], ts[order]), origin


# -- writing ------------------------------------------------------------------------------

_ROW_TEXT = ["".join("*" if b >> x & 1 else "." for x in range(8)).rstrip(".") + "$"
             for b in range(256)]


def _bitmap_text(bits: int) -> str:
    """An 8 x 8 leaf's line: rows ended by '$', trailing dots and empty rows left out."""
    rows = [_ROW_TEXT[(bits >> (8 * y)) & 0xFF] for y in range(8)]
    while rows and rows[-1] == "$":
        rows.pop()
    return "".join(rows)


def _leaves(xs: np.ndarray, ys: np.ndarray, ts: np.ndarray, two_state: bool
            ) -> tuple[np.ndarray, list[str]]:
    """Leaf positions (Morton-free: (x, y) packed) and their node lines' keys."""
    shift = 3 if two_state else 1
    key = (ys >> shift) * (1 << 32) + (xs >> shift)
    order = np.argsort(key, kind="stable")
    key, xs, ys, ts = key[order], xs[order], ys[order], ts[order]
    starts = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    if two_state:
        bit = np.left_shift(np.uint64(1), ((ys & 7) * 8 + (xs & 7)).astype(np.uint64))
        words = np.bitwise_or.reduceat(bit, starts)
        return key[starts], [_bitmap_text(int(w)) for w in words]
    quad = (ys & 1) * 2 + (xs & 1)
    packed = np.add.reduceat(ts << (8 * quad), starts)
    return key[starts], [" ".join(["1"] + [str((int(p) >> (8 * q)) & 0xFF) for q in range(4)])
                         for p in packed]


def format_mc(xs: np.ndarray, ys: np.ndarray, ts: np.ndarray, ref: tuple[int, int],
              rule: str = "", comments: list[str] | None = None) -> str:
    """A macrocell file of the cells, Golly's origin at the reference point ``ref``."""
    dx, dy = xs - ref[0], ys - ref[1]
    two_state = not ts.size or int(ts.max()) <= 1
    level = 4 if two_state else 3
    while ts.size and (int(dx.min()) < -(1 << (level - 1)) or int(dx.max()) >= 1 << (level - 1)
                       or int(dy.min()) <= -(1 << (level - 1)) or int(dy.max()) > 1 << (level - 1)):
        level += 1
    head = ["[M2] (camlab88)"]
    if rule:
        head.append(f"#R {rule}")
    head += [f"#C {c}" for c in (comments or [])]
    if not ts.size:
        return "\n".join(head + [f"{level} 0 0 0 0"]) + "\n"
    half = 1 << (level - 1)
    keys, texts = _leaves(dx + half, dy + half - 1, ts, two_state)
    lines: list[str] = []
    ids: dict[str, int] = {}

    def node(text: str) -> int:
        if text not in ids:
            lines.append(text)
            ids[text] = len(lines)
        return ids[text]

    kid = np.array([node(t) for t in texts], np.int64)
    kx, ky = keys % (1 << 32), keys // (1 << 32)
    for lv in range((3 if two_state else 1) + 1, level + 1):
        px, py = kx >> 1, ky >> 1
        pk = py * (1 << 32) + px
        order = np.argsort(pk, kind="stable")
        pk, q, kid = pk[order], ((ky & 1) * 2 + (kx & 1))[order], kid[order]
        starts = np.flatnonzero(np.r_[True, pk[1:] != pk[:-1]])
        quads = np.zeros((starts.size, 4), np.int64)
        quads[np.searchsorted(pk[starts], pk), q] = kid
        kid = np.array([node(f"{lv} {a} {b} {c} {d}") for a, b, c, d in quads.tolist()],
                       np.int64)
        kx, ky = pk[starts] % (1 << 32), pk[starts] // (1 << 32)
    return "\n".join(head + _golly_order(lines)) + "\n"


def _golly_order(lines: list[str]) -> list[str]:
    """The node lines renumbered in the order Golly writes them: each node right after
    its quadrants (nw, ne, sw, se), depth first from the root (the last line)."""
    new: dict[int, int] = {}
    out: list[str] = []

    def visit(k: int) -> int:
        if k == 0:
            return 0
        if k not in new:
            text = lines[k - 1]
            parts = text.split()
            if len(parts) == 5 and parts[0] != "1":
                kids = [visit(int(c)) for c in parts[1:]]
                text = " ".join([parts[0], *map(str, kids)])
            out.append(text)
            new[k] = len(out)
        return new[k]

    visit(len(lines))
    return out
