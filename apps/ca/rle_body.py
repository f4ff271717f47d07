"""The cell data of an RLE pattern (after its header), decoded with numpy.

The body is a run of tokens — an optional repeat count and a symbol (``b`` ``.`` dead, ``o``
alive, ``A``..``X`` and ``pA``..``yO`` states 1..255, ``$`` next row, ``!`` end) — with
whitespace between tokens. One regular expression splits it; the rows and columns of every
run then come from cumulative sums, so a 24 KB RLE of 4000x4000 live cells decodes in a
fraction of a second instead of a Python step per cell. Errors name the
line and column of the offending character, as the old character-by-character reader did.
"""

from __future__ import annotations

import re
from collections.abc import Callable

import numpy as np

from camlab88.base import budget

PLANE = 65536  # the CA plane is 65536 cells square (section 7.3)
MAX_STATE = 255
_TOKEN = re.compile(r"([1-9][0-9]{0,5})?([bo.$!A-X]|[p-y][A-X])|\s+")
Fail = Callable[[int, str], Exception]  # (offset into the body, message) -> the error


def _state(sym: str) -> int:
    if sym in "b.$!":
        return 0
    if sym == "o":
        return 1
    if len(sym) == 1:
        return ord(sym) - ord("A") + 1
    return 25 + (ord(sym[0]) - ord("p")) * 24 + ord(sym[1]) - ord("A")


def _why(body: str, at: int) -> str:
    """What is wrong at ``at``, where no token matches (the old reader's messages)."""
    ch = body[at]
    digits = re.match(r"[0-9]*", body[at:]).group()
    if ch == "0":
        return "repeat counts have no leading zero"
    if len(digits) > 6:
        return "pattern is wider or taller than the 65536-cell plane"
    nxt = body[at + len(digits): at + len(digits) + 1]
    if digits and (nxt == "" or nxt.isspace()):
        return "expected a cell symbol after the repeat count"
    if digits:
        return _why(body, at + len(digits))
    if "p" <= ch <= "y":
        return f"expected A..X after '{ch}', found '{body[at + 1: at + 2]}'"
    return f"expected b, o, ., A..X, $ or !, found '{ch}'"


def _tokens(body: str, fail: Fail) -> tuple[list[str], list[str], np.ndarray]:
    """(counts, symbols, offsets) of the tokens up to and including the first '!'."""
    counts: list[str] = []
    syms: list[str] = []
    offsets: list[int] = []
    at = 0
    for m in _TOKEN.finditer(body):
        if m.start() != at:  # finditer skipped something no token matches
            raise fail(at, _why(body, at))
        at = m.end()
        if m.group(2):
            counts.append(m.group(1) or "")
            syms.append(m.group(2))
            offsets.append(m.start())
            if m.group(2) == "!":
                return counts, syms, np.array(offsets, np.int64)
    if at < len(body):
        raise fail(at, _why(body, at))
    raise fail(len(body), "expected '!' ending the RLE pattern")


def decode_body(body: str, fail: Fail, source: str = "<rle>"
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(xs, ys, states) of the live cells, sorted by row then column (a few bytes of
    repeat counts can ask for 10^9 cells: over the memory budget they are refused)."""
    counts, syms, offsets = _tokens(body, fail)
    n = np.array([int(c) if c else 1 for c in counts], np.int64)
    state = np.array([_state(s) for s in syms], np.int64)
    high = np.flatnonzero(state > MAX_STATE)
    if high.size:
        raise fail(int(offsets[high[0]]) + len(counts[high[0]]) + 1,
                   f"state {int(state[high[0]])} is above 255")
    newline = np.array([s == "$" for s in syms], bool)
    run = ~newline & (np.array([s != "!" for s in syms], bool))
    ys = np.cumsum(np.where(newline, n, 0)) - np.where(newline, n, 0)  # row of each token
    width = np.where(run, n, 0)
    before = np.cumsum(width) - width  # cells before the token, all rows
    row_start = np.maximum.accumulate(np.where(newline, np.cumsum(width), 0))
    xs = before - row_start
    bad = np.flatnonzero(run & ((xs + n > PLANE) | (ys >= PLANE)))
    if bad.size:
        raise fail(int(offsets[bad[0]]), "pattern is wider or taller than the 65536-cell plane")
    live = np.flatnonzero(run & (state > 0))
    reps = n[live]
    total = int(reps.sum())
    budget.check(source, total * 2 * CELL_BYTES, f"its {total:,} live cells")
    # x of cell k of a run = its run's x + (k - index of the run's first cell); built in
    # place so a 16-million-cell pattern needs one temporary array, not three
    cell_x = np.arange(total, dtype=np.int64)
    cell_x -= np.repeat(np.cumsum(reps) - reps - xs[live], reps)
    return cell_x, np.repeat(ys[live], reps), np.repeat(state[live], reps)


# A pattern filling at least 1/GRID_FILL of its box is decoded into a uint8 grid (a byte a
# cell) rather than cell arrays (24 bytes a live cell): smaller from 1/24 full.
GRID_FILL = 16


SCAN_BYTES = 13  # the compiled scanner's arrays: three int32 and a uint8 per body byte
CELL_BYTES = 24  # a live cell listed: x, y and state as int64
# A grid's cell costs its byte and, once it runs, the engine's padded window and step
# buffers: checked at that cost when read, so a grid no command can use is never made
# (an 8192 x 8192 grid ran in 408 MB, a 30000 x 30000 one took 2.8 GB)
GRID_BYTES = 4


def decode_compiled(body: str, fail: Fail, source: str = "<rle>"
                    ) -> tuple[tuple[np.ndarray, np.ndarray, np.ndarray] | np.ndarray,
                               tuple[int, int]]:
    """The live cells as (xs, ys, states) or, for a dense pattern, a uint8 grid of states;
    both relative to the live cells' top-left corner, which is returned as (x, y).  Bodies
    the compiled scanner does not take as they are (a fault, non-ASCII whitespace) go to
    the token reader, which words the error or decodes what Python's ``\\s`` allows."""
    from camlab88.apps.ca import rle_scan

    budget.check(source, len(body) * (SCAN_BYTES + 1), f"scanning its {len(body):,}-byte body")
    raw = body.encode("utf-8", "replace")
    b = np.frombuffer(raw, np.uint8)
    ry, rx, rn = (np.empty(b.shape[0], np.int32) for _ in range(3))
    rs = np.empty(b.shape[0], np.uint8)
    res = rle_scan.scan(b, ry, rx, rn, rs)
    status, at, _end, runs, cells, top, bottom, left, right, _big = (int(v) for v in res)
    odd_space = status == rle_scan.SYNTAX and at < len(body) and body[at].isspace()
    if status != rle_scan.OK and len(raw) == len(body) and not odd_space:
        # ASCII, so byte offsets are columns; the fault is not a space only Python knows
        if status == rle_scan.HIGH_STATE:
            sym = body[at - 1: at + 1]
            raise fail(at, f"state {_state(sym)} is above 255")
        if status == rle_scan.TOO_WIDE:
            raise fail(at, "pattern is wider or taller than the 65536-cell plane")
        raise fail(at, _why(body, at) if at < len(body) else
                   "expected '!' ending the RLE pattern")
    if status != rle_scan.OK:
        xs, ys, ts = decode_body(body, fail, source)
        return (xs, ys, ts), (0, 0)
    if cells == 0:
        empty = np.zeros(0, np.int64)
        return (empty, empty, empty), (0, 0)
    h, w = bottom - top + 1, right - left + 1
    if cells * GRID_FILL >= h * w:
        budget.check(source, h * w * GRID_BYTES, f"its {w:,} x {h:,} grid")
        grid = np.zeros((h, w), np.uint8)
        rle_scan.to_grid(ry, rx, rn, rs, runs, grid, top, left)
        return grid, (left, top)
    budget.check(source, cells * CELL_BYTES, f"its {cells:,} live cells")
    xs, ys, ts = (np.empty(cells, np.int64) for _ in range(3))
    rle_scan.to_cells(ry, rx, rn, rs, runs, xs, ys, ts, top, left)
    return (xs, ys, ts), (left, top)


# Bodies shorter than this are read by the token reader: a few ms at most, where the first
# use of the compiled scanner loads its kernels from numba's cache (30-60 ms of CPU, as
# much as a whole short HashLife jump). Measured in docs/perf/ca.md.
SMALL_BODY = 8192


def decode(body: str, fail: Fail, source: str = "<rle>"
           ) -> tuple[tuple[np.ndarray, np.ndarray, np.ndarray] | np.ndarray, tuple[int, int]]:
    """What :func:`decode_compiled` returns — cells or, dense, a grid, and the corner —
    by whichever reader is quicker for the body's size (a grid or cell list over the
    memory budget is refused before it is made, naming ``source``)."""
    if len(body) >= SMALL_BODY:
        return decode_compiled(body, fail, source)
    xs, ys, ts = decode_body(body, fail, source)
    if xs.size == 0:
        return (xs, ys, ts), (0, 0)
    left, top = int(xs.min()), int(ys.min())
    xs -= left
    ys -= top
    h, w = int(ys.max()) + 1, int(xs.max()) + 1
    if xs.size * GRID_FILL >= h * w:
        budget.check(source, h * w * GRID_BYTES, f"its {w:,} x {h:,} grid")
        grid = np.zeros((h, w), np.uint8)
        grid[ys, xs] = ts
        return grid, (left, top)
    return (xs, ys, ts), (left, top)
