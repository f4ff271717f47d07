"""Patterns: the native format, RLE (as Golly and the LifeWiki write it), plaintext .cells,
Golly's macrocell and Life 1.05/1.06 (read only).

A :class:`Pattern` is a set of (x, y, life-form) cells relative to its own top-left corner
plus the reference point the thesis's "save pattern" asks for (section 7.3.2).  It can be
placed on an :class:`~apps.ca.engine.Engine` in any of the eight orientations.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field

import numpy as np

from camlab88.apps.ca import life_pc, macrocell
from camlab88.apps.ca.rle_body import GRID_BYTES, decode
from camlab88.base import atomicfile, budget
from camlab88.base.textinput import InputError, quote, read_text, where

NATIVE_MAGIC = "CAMLAB88-CA-PATTERN 1"
MAX_RLE_STATE = 255
# The eight orientations: (a, b, c, d) maps (dx, dy) -> (a*dx + b*dy, c*dx + d*dy).
ORIENTATIONS: dict[str, tuple[int, int, int, int]] = {
    "identity": (1, 0, 0, 1),
    "rot90": (0, -1, 1, 0),  # clockwise on a y-down screen
    "rot180": (-1, 0, 0, -1),
    "rot270": (0, 1, -1, 0),
    "flip_x": (-1, 0, 0, 1),  # mirror left-right
    "flip_y": (1, 0, 0, -1),  # mirror top-bottom
    "transpose": (0, 1, 1, 0),  # mirror in the main diagonal
    "antitranspose": (0, -1, -1, 0),
}


class PatternError(ValueError):
    """A pattern file is malformed; the message names the file, line and column."""

    def __init__(self, source: str, line: int, column: int, message: str) -> None:
        super().__init__(f"{where(source, line or None, column or None)}: {message}")
        self.line = line
        self.column = column


@dataclass
class Pattern:
    xs: np.ndarray  # int64, relative to the pattern's top-left corner
    ys: np.ndarray
    ts: np.ndarray  # life-forms, all > 0
    ref: tuple[int, int] = (0, 0)
    name: str = ""
    rule: str = ""
    comments: list[str] = field(default_factory=list)
    author: str = ""  # RLE '#O' lines (one per line of text)

    @classmethod
    def from_cells(cls, cells: list[tuple[int, int, int]], **kw) -> Pattern:
        """Normalised (top-left at 0, 0, sorted, unique) pattern from (x, y, type) triples."""
        live = [(x, y, t) for x, y, t in cells if t > 0]
        if not live:
            return cls(np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0, np.int64), **kw)
        a = np.array(live, np.int64)
        return cls(a[:, 0], a[:, 1], a[:, 2], **kw).normalised()

    def shifted_to_origin(self) -> Pattern:
        """The pattern with its top-left live cell's box at (0, 0) — for cells that are
        already unique and in row order (the RLE and .cells decoders make them so)."""
        if self.xs.size == 0:
            return self
        x0, y0 = int(self.xs.min()), int(self.ys.min())
        return Pattern(self.xs - x0, self.ys - y0, self.ts, (self.ref[0] - x0,
                       self.ref[1] - y0), self.name, self.rule, self.comments, self.author)

    def normalised(self) -> Pattern:
        if self.xs.size == 0:
            return self
        x0, y0 = int(self.xs.min()), int(self.ys.min())
        xs, ys = self.xs - x0, self.ys - y0
        keys = ys * (1 << 32) + xs
        keys, idx = np.unique(keys[::-1], return_index=True)  # last duplicate wins
        ts = self.ts[::-1][idx]
        return Pattern(keys % (1 << 32), keys // (1 << 32), ts, (self.ref[0] - x0,
                       self.ref[1] - y0), self.name, self.rule, list(self.comments),
                       self.author)

    @property
    def width(self) -> int:
        return int(self.xs.max()) + 1 if self.xs.size else 0

    @property
    def height(self) -> int:
        return int(self.ys.max()) + 1 if self.ys.size else 0

    def placed_grid(self, x: int, y: int, orientation: str = "identity"
                    ) -> tuple[int, int, np.ndarray] | None:
        """(left, top, uint8 grid) of a dense pattern placed as :meth:`placed` places its
        cells; None for a sparse pattern or one that would wrap round the plane."""
        return None

    def cell_set(self) -> set[tuple[int, int, int]]:
        return {(int(x), int(y), int(t)) for x, y, t in zip(self.xs, self.ys, self.ts)}

    def placed(self, x: int, y: int, orientation: str = "identity"
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Plane positions when the reference point goes to (x, y) in ``orientation``
        (positions wrap round the 65536-cell plane)."""
        if orientation not in ORIENTATIONS:
            raise ValueError(f"unknown orientation {orientation!r}; one of "
                             f"{', '.join(ORIENTATIONS)}")
        a, b, c, d = ORIENTATIONS[orientation]
        dx = self.xs - self.ref[0]
        dy = self.ys - self.ref[1]
        return ((x + a * dx + b * dy) % 65536, (y + c * dx + d * dy) % 65536, self.ts.copy())


class GridPattern(Pattern):
    """A dense pattern kept as a uint8 grid of life-forms (row y, column x; its top-left
    cell is the pattern's (0, 0), and its edges hold live cells): a byte a cell instead of
    24 a live cell.  The cell arrays are made only when something asks for them."""

    def __init__(self, grid: np.ndarray, ref: tuple[int, int] = (0, 0), name: str = "",
                 rule: str = "", comments: list[str] | None = None, author: str = "") -> None:
        self.grid = grid
        self.ref, self.name, self.rule, self.author = ref, name, rule, author
        self.comments = list(comments or [])
        self._cells: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None

    def _cell_arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        if self._cells is None:
            ys, xs = np.nonzero(self.grid)
            self._cells = (xs.astype(np.int64), ys.astype(np.int64),
                           self.grid[ys, xs].astype(np.int64))
        return self._cells

    xs = property(lambda self: self._cell_arrays()[0])
    ys = property(lambda self: self._cell_arrays()[1])
    ts = property(lambda self: self._cell_arrays()[2])

    @property
    def width(self) -> int:
        return int(self.grid.shape[1])

    @property
    def height(self) -> int:
        return int(self.grid.shape[0])

    def placed_grid(self, x: int, y: int, orientation: str = "identity"
                    ) -> tuple[int, int, np.ndarray] | None:
        return _oriented_grid(self.grid, self.ref, x, y, orientation)


def _oriented_grid(grid: np.ndarray, ref: tuple[int, int], x: int, y: int,
                   orientation: str) -> tuple[int, int, np.ndarray] | None:
    """(left, top, grid) of ``grid`` placed as Pattern.placed places its cells; None if it
    would cross the plane's edge (then the cells wrap, which a grid cannot)."""
    if orientation not in ORIENTATIONS:
        raise ValueError(f"unknown orientation {orientation!r}; one of "
                         f"{', '.join(ORIENTATIONS)}")
    a, b, c, d = ORIENTATIONS[orientation]
    h, w = grid.shape
    if a == 0:  # the axes swap: column x' comes from row y (times b), row y' from x (c)
        g = grid.T
        g = g[::-1] if c < 0 else g
        g = g[:, ::-1] if b < 0 else g
    else:
        g = grid[::-1] if d < 0 else grid
        g = g[:, ::-1] if a < 0 else g
    corners = [(cx - ref[0], cy - ref[1]) for cx in (0, w - 1) for cy in (0, h - 1)]
    left = x + min(a * dx + b * dy for dx, dy in corners)
    top = y + min(c * dx + d * dy for dx, dy in corners)
    if left < 0 or top < 0 or left + g.shape[1] > 65536 or top + g.shape[0] > 65536:
        return None
    return left, top, np.ascontiguousarray(g)


# -- files ---------------------------------------------------------------------------------

def format_of(path: str) -> str:
    low = path.lower()
    if low.endswith(".rle"):
        return "rle"
    if low.endswith(".cells"):
        return "cells"
    if low.endswith(".mc"):
        return "mc"
    if low.endswith((".lif", ".life")):
        return "life"
    return "native"


def read_pattern(path: str | os.PathLike) -> Pattern:
    """A pattern file in the format its name says; a bad file (a directory, a bad byte, a
    bad line) raises PatternError naming the file, line and column."""
    path = os.fspath(path)
    try:
        text = read_text(path)
    except InputError as exc:
        raise PatternError(path, exc.line, exc.column, exc.reason) from None
    return parse_pattern(text, format_of(path), source=path)


def parse_pattern(text: str, fmt: str, source: str = "<pattern>") -> Pattern:
    if fmt == "rle":
        return parse_rle(text, source)
    if fmt == "cells":
        return parse_cells(text, source)
    if fmt == "mc":
        return parse_mc(text, source)
    if fmt == "life":
        return parse_life(text, source)
    return parse_native(text, source)


# What writing a cell costs in each format, measured order of magnitude: RLE and native
# go through Python values a cell (~200 bytes), macrocell through numpy sorts and a leaf's
# text; a plaintext .cells is a character per cell of its box. A grid pattern's cells are
# listed first (24 bytes each).
WRITE_CELL_BYTES = {"rle": 200, "native": 200, "mc": 120, "cells": 0}
WRITE_BOX_BYTES = {"rle": 0, "native": 0, "mc": 0, "cells": 10}


def population(pattern: Pattern) -> int:
    """Live cells, without listing a grid pattern's."""
    if isinstance(pattern, GridPattern):
        return int(np.count_nonzero(pattern.grid))
    return int(pattern.xs.size)


def check_write(path: str, pattern: Pattern, source: str = "") -> None:
    """Refuse (base.budget) a pattern (read from ``source``) whose file in ``path``'s
    format would need more memory to write than the budget allows — before any cell is
    listed."""
    fmt = format_of(path)
    cells = population(pattern)
    need = cells * (WRITE_CELL_BYTES.get(fmt, 200) + 24) + \
        pattern.width * pattern.height * WRITE_BOX_BYTES.get(fmt, 0)
    budget.check(source or path, need, f"writing its {cells:,} live cells to {path} as {fmt}")


# What running a pattern costs (ca run): a dense pattern's box as its reader checked it
# (rle_body.GRID_BYTES), a listed cell ~100 bytes (the engine's arrays, sorted and merged)
RUN_BOX_BYTES = GRID_BYTES
RUN_CELL_BYTES = 100


def check_run(source: str, pattern: Pattern) -> None:
    """Refuse a pattern whose run would need more memory than the budget allows."""
    if isinstance(pattern, GridPattern):
        need = pattern.width * pattern.height * RUN_BOX_BYTES
        what = f"running its {pattern.width:,} x {pattern.height:,} grid"
    else:
        need = int(pattern.xs.size) * RUN_CELL_BYTES
        what = f"running its {int(pattern.xs.size):,} live cells"
    budget.check(source, need, what)


def write_pattern(path: str | os.PathLike, pattern: Pattern) -> None:
    path = os.fspath(path)
    fmt = format_of(path)
    if fmt == "life":
        raise ValueError(f"{path}: Life 1.05/1.06 is read, not written; save as .rle, "
                         ".cells, .mc or native")
    check_write(path, pattern)
    text = {"rle": format_rle, "cells": format_cells, "native": format_native,
            "mc": format_mc}[fmt](pattern)
    atomicfile.write_atomic(path, text)


# -- native --------------------------------------------------------------------------------
# CAMLAB88-CA-PATTERN 1
# name <text>            (optional)
# rules <text>           (optional: the rule set the pattern was made for)
# author <text>          (any number: RLE '#O' lines)
# comment <text>         (any number)
# ref <x> <y>            (reference point, pattern coordinates)
# cells <n>
# <x> <y> <life-form>    (n lines, any order)
# end

def format_native(p: Pattern) -> str:
    lines = [NATIVE_MAGIC]
    if p.name:
        lines.append(f"name {p.name}")
    if p.rule:
        lines.append(f"rules {p.rule}")
    lines += [f"author {a}" for a in p.author.splitlines()]
    lines += [f"comment {c}" for c in p.comments]
    lines.append(f"ref {p.ref[0]} {p.ref[1]}")
    lines.append(f"cells {p.xs.size}")
    lines += [f"{x} {y} {t}" for x, y, t in zip(p.xs.tolist(), p.ys.tolist(), p.ts.tolist())]
    lines.append("end")
    return "\n".join(lines) + "\n"


@dataclass
class _About:
    """What a pattern file's header lines say about the pattern, gathered as they come."""

    name: str = ""
    rule: str = ""
    comments: list[str] = field(default_factory=list)
    authors: list[str] = field(default_factory=list)

    def fields(self) -> tuple[str, str, list[str], str]:
        """Name, rule, comments and author, in Pattern's order."""
        return self.name, self.rule, self.comments, "\n".join(self.authors)


def parse_native(text: str, source: str = "<pattern>") -> Pattern:
    lines = text.splitlines()
    if not lines or lines[0].strip() != NATIVE_MAGIC:
        raise PatternError(source, 1, 1, f"expected '{NATIVE_MAGIC}' on the first line")
    about = _About()
    ref = (0, 0)
    i = 1
    count = None
    while i < len(lines):
        raw = lines[i]
        i += 1
        word, _, rest = raw.strip().partition(" ")
        if word == "":
            continue
        if word == "name":
            about.name = rest
        elif word == "rules":
            about.rule = rest
        elif word == "comment":
            about.comments.append(rest)
        elif word == "author":
            about.authors.append(rest)
        elif word == "ref":
            ref = _ints(rest, 2, source, i, raw, "'ref x y'")
        elif word == "cells":
            (count,) = _ints(rest, 1, source, i, raw, "'cells n'")
            if count < 0:
                raise PatternError(source, i, 1, f"a cell count cannot be negative ({count})")
            break
        else:
            raise PatternError(source, i, 1, f"expected name, rules, author, comment, ref or "
                                             f"cells, "
                                             f"found '{word}'")
    if count is None:
        raise PatternError(source, len(lines), 1, "expected 'cells n' before end of file")
    xs, ys, ts = _native_cells(lines, i, count, source)
    i += count
    while i < len(lines) and not lines[i].strip():
        i += 1
    if i >= len(lines) or lines[i].strip() != "end":
        raise PatternError(source, i + 1, 1, "expected 'end' after the cell lines")
    p = Pattern(xs, ys, ts, ref, *about.fields()).normalised()
    if not xs.size:
        p.ref = ref
    return p


# a coordinate of more than 10 digits cannot be on (or relative to) the 65536-cell plane
_CELL_LINE = re.compile(r"[ \t]*-?[0-9]{1,10}[ \t]+-?[0-9]{1,10}[ \t]+[0-9]{1,5}[ \t]*")
_CELL_BLOCK = re.compile(rf"(?:{_CELL_LINE.pattern}\n)*")


def _native_cells(lines: list[str], i: int, count: int, source: str
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The ``count`` cell lines from line index ``i``, checked and converted with numpy."""
    if len(lines) - i < count:
        raise PatternError(source, len(lines), 1, f"expected {count} cell lines 'x y "
                                                  "life-form', file ended early")
    block = lines[i: i + count]
    if not _CELL_BLOCK.fullmatch("\n".join(block) + "\n" if block else ""):
        k = next(k for k, raw in enumerate(block) if not _CELL_LINE.fullmatch(raw))
        _ints(block[k], 3, source, i + k + 1, block[k], "'x y life-form'")  # names the fault
        raise PatternError(source, i + k + 1, 1, f"a coordinate in {quote(block[k].strip())} "
                                                 "is too far out for the 65536-cell plane")
    a = np.array(" ".join(block).split(), dtype=np.int64).reshape(-1, 3)
    bad = np.flatnonzero((a[:, 2] < 1) | (a[:, 2] > 65535))
    if bad.size:
        raise PatternError(source, i + int(bad[0]) + 1, 1,
                           f"life-form must be 1..65535, found {int(a[bad[0], 2])}")
    for axis in (0, 1):
        if a.size and int(a[:, axis].max()) - int(a[:, axis].min()) >= 65536:
            far = int(np.argmax(a[:, axis]))
            raise PatternError(source, i + far + 1, 1, "pattern is wider or taller than the "
                                                       "65536-cell plane")
    return a[:, 0].copy(), a[:, 1].copy(), a[:, 2].copy()


def _ints(text: str, n: int, source: str, line: int, raw: str, what: str) -> tuple[int, ...]:
    parts = text.split()
    if len(parts) != n or not all(re.fullmatch(r"-?[0-9]+", s) for s in parts):
        raise PatternError(source, line, 1, f"expected {what}, found {quote(raw.strip())}")
    if any(len(s.lstrip("-")) > 10 for s in parts):
        raise PatternError(source, line, 1, f"a number in {quote(raw.strip())} is too large "
                                            "for the 65536-cell plane")
    return tuple(int(s) for s in parts)


# -- RLE -------------------------------------------------------------------------------------

# A library rule set (not a Golly rule) is named in a comment line, which Golly ignores.
RULES_COMMENT = "#C camlab88 rules: "
# Library rule sets that are Golly rules: the header gets the Golly rule string.
GOLLY_NAMES = {"life": "B3/S23", "wireworld": "WireWorld", "langtons_loops": "Langtons-Loops"}
# Golly rule tables kept by name when a pattern made for them is written out again.
GOLLY_TABLES = {"WireWorld", "Langtons-Loops"}
# B/S and S/B notation, Generations (/C n), hexagonal/von Neumann suffixes, and a bounded
# grid topology (':T100,100').
_GOLLY_RULE = re.compile(
    r"(?:[Bb][0-8]*/[Ss][0-8]*(?:/[Cc]?[0-9]+|[VvHh])?|[Ss]?[0-8]*/[Bb]?[0-8]*(?:/[Cc]?[0-9]+)?)"
    r"(?::[PpTtKkCcSs][0-9,*+]*)?")


def golly_rule(rule: str) -> str | None:
    """The rule as Golly writes it in an RLE header, or None if Golly would not know it
    (a camlab88 rule set name such as 'overgrazing')."""
    rule = rule.strip()
    if rule.lower() in GOLLY_NAMES:
        return GOLLY_NAMES[rule.lower()]
    if rule in GOLLY_TABLES:
        return rule
    return rule if rule and _GOLLY_RULE.fullmatch(rule) else None


def _state_symbol(t: int, multi: bool) -> str:
    if not multi:
        return "o" if t else "b"
    if t == 0:
        return "."
    if t <= 24:
        return chr(ord("A") + t - 1)
    hi, lo = divmod(t - 25, 24)
    return chr(ord("p") + hi) + chr(ord("A") + lo)


def format_rle(p: Pattern) -> str:
    if p.ts.size and int(p.ts.max()) > MAX_RLE_STATE:
        raise ValueError(f"RLE holds life-forms up to {MAX_RLE_STATE}; this pattern has "
                         f"{int(p.ts.max())} (use the native format)")
    multi = bool(p.ts.size and int(p.ts.max()) > 1)
    head: list[str] = []
    if p.name:
        head.append(f"#N {p.name}")
    head += [f"#O {a}" for a in p.author.splitlines()]
    head += [f"#C {c}" for c in p.comments]
    golly = golly_rule(p.rule)
    if p.rule and golly is None:  # Golly rejects unknown rule names in the header
        head.append(f"{RULES_COMMENT}{p.rule}")
    head.append(f"#CXRLE Pos={-p.ref[0]},{-p.ref[1]}")  # reference point = Golly's origin
    rule = f", rule = {golly}" if golly else ""
    head.append(f"x = {p.width}, y = {p.height}{rule}")
    rows: dict[int, list[tuple[int, int]]] = {}
    for x, y, t in zip(p.xs.tolist(), p.ys.tolist(), p.ts.tolist()):
        rows.setdefault(y, []).append((x, t))
    items: list[str] = []
    prev_y = 0
    for y in sorted(rows):
        if y > prev_y:
            gap = y - prev_y
            items.append(f"{gap}$" if gap > 1 else "$")
        prev_y = y
        col = 0
        runs: list[tuple[int, int]] = []  # (count, state)
        for x, t in sorted(rows[y]):
            if x > col:
                runs.append((x - col, 0))
            if runs and runs[-1][1] == t:
                runs[-1] = (runs[-1][0] + 1, t)
            else:
                runs.append((1, t))
            col = x + 1
        for n, t in runs:
            sym = _state_symbol(t, multi)
            items.append(f"{n}{sym}" if n > 1 else sym)
    items.append("!")
    return "\n".join(head + rle_lines(items)) + "\n"


def rle_lines(tokens: list[str], width: int = 70) -> list[str]:
    """RLE run tokens joined into lines of at most ``width`` columns, cut only between tokens
    (as Golly writes them)."""
    lines: list[str] = []
    line = ""
    for t in tokens:
        if len(line) + len(t) > width:
            lines.append(line)
            line = ""
        line += t
    lines.append(line)
    return lines


_HEADER = re.compile(
    r"\s*x\s*=\s*([0-9]+)\s*,\s*y\s*=\s*([0-9]+)\s*(?:,\s*rule\s*=\s*(\S.*?))?\s*$", re.IGNORECASE)


def parse_rle(text: str, source: str = "<rle>") -> Pattern:
    lines = text.splitlines()
    about = _About()
    pos = (0, 0)
    i = 0
    header = None
    while i < len(lines):
        s = lines[i].strip()
        i += 1
        if not s:
            continue
        if s.startswith("#"):
            tag, _, rest = s.partition(" ")
            if s.startswith(RULES_COMMENT.strip()):
                about.rule = s[len(RULES_COMMENT.strip()):].strip()
            elif tag == "#N":
                about.name = rest.strip()
            elif tag == "#O":
                about.authors.append(rest.strip())
            elif tag in ("#C", "#c"):
                about.comments.append(rest.strip())
            elif tag == "#r":
                about.rule = rest.strip()
            elif tag == "#CXRLE":
                m = re.search(r"Pos\s*=\s*(-?[0-9]{1,6})\s*,\s*(-?[0-9]{1,6})(?![0-9])", rest)
                if m:  # a reference point further than the plane is wide means nothing
                    pos = (int(m.group(1)), int(m.group(2)))
            continue
        header = _HEADER.match(s)
        if not header:
            raise PatternError(source, i, 1, "expected the RLE header 'x = m, y = n[, rule = "
                                             f"R]', found '{s[:40]}'")
        about.rule = header.group(3) or about.rule
        break
    if header is None:
        raise PatternError(source, max(1, len(lines)), 1, "expected the RLE header "
                                                          "'x = m, y = n', found end of file")
    body_line = i  # 0-based index of the first body line
    body = "\n".join(lines[i:])

    def fail(offset: int, message: str) -> PatternError:
        line = body.count("\n", 0, offset)
        col = offset - (body.rfind("\n", 0, offset) + 1) + 1
        return PatternError(source, min(body_line + line + 1, max(1, len(lines))), col, message)

    cells, (left, top) = decode(body, fail, source)
    # Golly reads cells beyond the header's box too; so do we. The reference point is
    # Golly's origin: Pos gives the box corner relative to it.
    ref = (-pos[0] - left, -pos[1] - top)
    if isinstance(cells, np.ndarray):
        return GridPattern(cells, ref, *about.fields())
    return Pattern(*cells, ref, *about.fields()).shifted_to_origin()


# -- Golly's macrocell (.mc) ---------------------------------------------------------------

def parse_mc(text: str, source: str = "<mc>") -> Pattern:
    """A macrocell file (apps/ca/macrocell.py); Golly's origin becomes the reference point."""
    try:
        tree, rule, comments = macrocell.read_tree(text, source)
        cells, ref = macrocell.cells_of(tree, max(1, text.count("\n")), source)
    except macrocell.McError as exc:
        raise PatternError(source, exc.line, exc.column, str(exc)) from None
    if isinstance(cells, np.ndarray):
        return GridPattern(cells, ref, "", rule, comments)
    return Pattern(*cells, ref, "", rule, comments)


def format_mc(p: Pattern) -> str:
    golly = golly_rule(p.rule)
    comments = list(p.comments) + ([f"camlab88 rules: {p.rule}"] if p.rule and not golly
                                   else [])
    return macrocell.format_mc(p.xs, p.ys, p.ts, p.ref, golly or "", comments)


# -- Life 1.05 / 1.06 (.lif, .life) ----------------------------------------------------------

# What decoding Life 1.05/1.06 costs, measured (10^6 and 4x10^6 cells of either: 292-335
# bytes a cell): a live cell's pair, its triple and the pattern's arrays; a line's string
LIFE_CELL_BYTES = 340
LIFE_LINE_BYTES = 64


def parse_life(text: str, source: str = "<lif>") -> Pattern:
    """Golly's reading (apps/ca/life_pc.py); Golly's origin becomes the reference point.
    Refused (base.budget) before a line is split when its cells would pass the budget: at
    most a cell a ``*`` (1.05) and one a line starting with a digit or ``-`` (1.06)."""
    lines = text.count("\n") + 1
    cells = text.count("*") + sum(text.count("\n" + c) for c in "-0123456789")
    budget.check(source, lines * LIFE_LINE_BYTES + cells * LIFE_CELL_BYTES,
                 f"decoding its {lines:,} lines and up to {cells:,} live cells")
    try:
        cells, rule, comments = life_pc.parse_life_pc(text)
    except life_pc.LifeTextError as exc:
        raise PatternError(source, exc.line, exc.column, exc.message) from None
    pattern = Pattern.from_cells([(x, y, 1) for x, y in cells], rule=rule, comments=comments)
    if pattern.width > 65536 or pattern.height > 65536:
        raise PatternError(source, 0, 0, "pattern is wider or taller than the 65536-cell plane")
    return pattern


# -- plaintext .cells --------------------------------------------------------------------------

def format_cells(p: Pattern) -> str:
    if p.ts.size and int(p.ts.max()) > 1:
        raise ValueError("plaintext .cells holds one life-form only; use RLE or native")
    head = [f"!Name: {p.name}"] if p.name else []
    head += [f"!{c}" for c in p.comments]
    grid = [["."] * p.width for _ in range(p.height)]
    for x, y in zip(p.xs.tolist(), p.ys.tolist()):
        grid[y][x] = "O"
    return "\n".join(head + ["".join(r).rstrip(".") for r in grid]) + "\n"


# What decoding .cells costs: a character ~10 bytes (its row's string, the UTF-32 copy, the
# masks), a live cell ~64 (positions found, rows searched, the pattern's three arrays)
CELLS_TEXT_BYTES = 10
CELLS_LIVE_BYTES = 64


def parse_cells(text: str, source: str = "<cells>") -> Pattern:
    """Plaintext: '!' lines are comments ('!Name: ...' the name), every other line a row of
    '.' dead and 'O' (or 'o', '*') live cells. Decoded with numpy, so large
    patterns load in a fraction of a second."""
    live = sum(text.count(c) for c in "Oo*")
    budget.check(source, len(text) * CELLS_TEXT_BYTES + live * CELLS_LIVE_BYTES,
                 f"decoding its {len(text):,} characters and {live:,} live cells")
    name = ""
    comments: list[str] = []
    rows: list[str] = []
    row_lines: list[int] = []
    for lineno, raw in enumerate(text.splitlines(), start=1):
        if raw.startswith("!"):
            body = raw[1:].strip()
            if body.lower().startswith("name:"):
                name = body[5:].strip()
            else:
                comments.append(body)
            continue
        rows.append(raw.rstrip())
        row_lines.append(lineno)
    xs, ys = _cells_grid(rows, row_lines, source)
    return Pattern(xs, ys, np.ones(xs.size, np.int64), (0, 0), name, "", comments,
                   "").shifted_to_origin()


def _cells_grid(rows: list[str], row_lines: list[int], source: str
                ) -> tuple[np.ndarray, np.ndarray]:
    if len(rows) > 65536 or max(map(len, rows), default=0) > 65536:
        tall = len(rows) > 65536
        line = row_lines[65536] if tall else row_lines[max(range(len(rows)),
                                                           key=lambda k: len(rows[k]))]
        raise PatternError(source, line, 1, "pattern is wider or taller than the 65536-cell "
                                            "plane")
    codes = np.frombuffer("\n".join(rows).encode("utf-32-le"), np.uint32)
    starts = np.cumsum([0] + [len(r) + 1 for r in rows[:-1]]).astype(np.int64)
    live = np.isin(codes, _LIVE)
    bad = np.flatnonzero(~live & (codes != ord(".")) & (codes != ord("\n")))
    at = np.flatnonzero(live)
    y = np.searchsorted(starts, np.concatenate([bad[:1], at]), side="right") - 1
    if bad.size:
        k = int(y[0])
        col = int(bad[0] - starts[k])
        raise PatternError(source, row_lines[k], col + 1,
                           f"expected '.' or 'O', found {chr(int(codes[bad[0]]))!r}")
    y = y[1:] if bad.size else y
    return at - starts[y], y.astype(np.int64)


_LIVE = np.array([ord("O"), ord("o"), ord("*")], np.uint32)
