"""The cellular automaton engine: a sparse 65536 x 65536 plane stepped by message passing.

The state is one universe (apps/ca/universe.py) in the form of the algorithm that last
stepped it: for the direct engine three int64 arrays (row, column, life-form) sorted row by
row, the modern form of the thesis's figure 7.10 (rows with vectors of (position, type)),
or a dense grid while the population is dense; after HashLife jumps, its tree.  A step
sends messages only from living cells (inside the advance area, if one is set), so work is
proportional to the live cells and their message reach, never to the plane.  Deterministic:
the only randomness (section 8.1 probabilistic outcomes) is a hash of seed, position and
generation.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from camlab88.apps.ca import algorithms
from camlab88.apps.ca.rules import RuleSet
from camlab88.apps.ca.tables import compile_rules
from camlab88.apps.ca.universe import CellList, DenseGrid, Universe, distinct

DEFAULT_MEMORY = 512 << 20  # bytes of HashLife node table, as Golly's default "maximum memory"

SIDE = 65536
CENTRE = SIDE // 2
EDGES = ("wrap", "bounded")
# The dense workspace is used while the reach box has at most this many cells per sender
# (plus a constant), and never above the absolute cap; otherwise the hash table is used.
WINDOW_CELLS_PER_SENDER = 64
WINDOW_MIN = 1 << 16
WINDOW_MAX = 1 << 26
# The dense fast path keeps at least one live cell per this many window cells, and a
# margin of this many cells beyond the message reach so the window is not regrown often.
DENSE_MIN_FILL = 64
DENSE_MARGIN = 16
# The dense path runs the separable kernel (box sums, bit-set interpretation); False runs the
# plain one-pass-per-message kernel (kept as the reference the tests compare against).
DENSE_SEPARABLE = True


@dataclass(frozen=True)
class Rect:
    """Inclusive cell rectangle on the plane, columns x0..x1 and rows y0..y1 going right and
    down.  x0 > x1 (or y0 > y1) means it crosses the wrapping plane's seam: columns
    x0..65535 then 0..x1."""

    x0: int
    y0: int
    x1: int
    y1: int

    def __post_init__(self) -> None:
        if not all(0 <= v < SIDE for v in (self.x0, self.y0, self.x1, self.y1)):
            raise ValueError(f"rectangle {self.x0},{self.y0}..{self.x1},{self.y1} is not "
                             f"inside the {SIDE}x{SIDE} plane")

    @classmethod
    def from_corners(cls, xa: int, ya: int, xb: int, yb: int) -> Rect:
        """The rectangle between two corners, not crossing the seam."""
        return cls(min(xa, xb), min(ya, yb), max(xa, xb), max(ya, yb))

    @classmethod
    def dragged(cls, xa: int, ya: int, xb: int, yb: int) -> Rect:
        """The rectangle a user drags between two corners on the wrapping plane: per axis
        the shorter way round, which is the way the mouse went, since a view never spans
        half the plane (at most 752 x 32 = 24064 cells); it crosses the seam if need be."""
        def axis(a: int, b: int) -> tuple[int, int]:
            lo, hi = min(a, b), max(a, b)
            return (lo, hi) if hi - lo <= SIDE // 2 else (hi, lo)

        (x0, x1), (y0, y1) = axis(xa % SIDE, xb % SIDE), axis(ya % SIDE, yb % SIDE)
        return cls(x0, y0, x1, y1)

    @property
    def width(self) -> int:
        return (self.x1 - self.x0) % SIDE + 1

    @property
    def height(self) -> int:
        return (self.y1 - self.y0) % SIDE + 1

    @property
    def wraps(self) -> bool:
        return self.x0 > self.x1 or self.y0 > self.y1

    def parts(self) -> list[Rect]:
        """The rectangle split at the seam into up to four rectangles that do not cross it."""
        xs = [(self.x0, self.x1)] if self.x0 <= self.x1 else [(self.x0, SIDE - 1), (0, self.x1)]
        ys = [(self.y0, self.y1)] if self.y0 <= self.y1 else [(self.y0, SIDE - 1), (0, self.y1)]
        return [Rect(a, c, b, d) for c, d in ys for a, b in xs]

    def contains(self, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
        return (((xs - self.x0) % SIDE <= (self.x1 - self.x0) % SIDE)
                & ((ys - self.y0) % SIDE <= (self.y1 - self.y0) % SIDE))


FULL = Rect(0, 0, SIDE - 1, SIDE - 1)


def _wrapped_interval(values: np.ndarray) -> tuple[int, int]:
    """The shortest arc of the 65536-circle holding every value: it starts after the
    largest gap between neighbouring occupied coordinates (the seam counts as a gap)."""
    u = distinct(values)
    gaps = np.diff(u)
    wrap_gap = int(u[0]) + SIDE - int(u[-1])
    if gaps.size == 0 or wrap_gap >= int(gaps.max()):
        return int(u[0]), int(u[-1])
    i = int(np.argmax(gaps))
    return int(u[i + 1]), int(u[i])


def _sorted(ys: np.ndarray, xs: np.ndarray, ts: np.ndarray):
    order = np.argsort(ys * SIDE + xs, kind="stable")
    return ys[order], xs[order], ts[order]


def _cell_column(i: int, name: str) -> property:
    """The live cells' column ``i`` (ys, xs, ts) from whichever universe holds the state;
    setting it makes the state a cell list first."""

    def get(self: Engine) -> np.ndarray:
        return self.universe.cells()[i]

    def put(self: Engine, value: np.ndarray) -> None:
        setattr(self._list(), name, value)

    return property(get, put)


class Engine:
    """State of the plane plus the rules; the model behind the ``ca`` program.

    ``algorithm`` picks the stepping strategy (apps.ca.algorithms): "direct" (message
    passing, every rule set), "hashlife" (jumps, deterministic rules) or "auto"."""

    def __init__(self, rules: RuleSet | None = None, edges: str = "wrap", seed: int = 0,
                 algorithm: str = "direct") -> None:
        if edges not in EDGES:
            raise ValueError(f"edges must be one of {EDGES}, not {edges!r}")
        if algorithm not in algorithms.CHOICES:
            raise ValueError(f"algorithm must be one of {algorithms.CHOICES}, not "
                             f"{algorithm!r}")
        self.algorithm = algorithm
        self.hashlife_memory = DEFAULT_MEMORY  # bytes of HashLife node table (Golly's limit)
        self.rules = rules
        self.edges = edges
        self.seed = int(seed)
        self.generation = 0
        self.advance_area: Rect | None = None
        # The state, in the form of the algorithm that last stepped it (apps.ca.universe):
        # a cell list, a dense grid or a HashLife tree; edits turn it into a cell list.
        self.universe: Universe = CellList()
        self._buffers: tuple[np.ndarray, np.ndarray] | None = None
        self._hash: tuple[np.ndarray, np.ndarray] | None = None
        self._sep_scratch: tuple[np.ndarray, ...] | None = None
        self.last_kernel = ""

    # -- the universe ----------------------------------------------------------------
    def _list(self) -> CellList:
        """The universe as a cell list (converted, for editing or the direct engine)."""
        u = self.universe
        if not isinstance(u, CellList):
            ys, xs, ts = u.cells()
            u = self.universe = CellList(ys, xs, ts)
        return u

    def adopt(self, universe: Universe) -> None:
        """Take ``universe`` (an algorithm's form of the state) as the plane."""
        self.universe = universe

    @property
    def tree(self) -> Universe | None:
        """The HashLife tree that is the state, if it is one (read only)."""
        u = self.universe
        return None if isinstance(u, (CellList, DenseGrid)) else u

    ys = _cell_column(0, "ys")
    xs = _cell_column(1, "xs")
    ts = _cell_column(2, "ts")

    # -- rules and options ------------------------------------------------------
    def set_rules(self, rules: RuleSet) -> None:
        """Change rules (mid-run too); life-forms without rules die next generation."""
        compile_rules(rules)
        self._list()  # a tree's node table belongs to the old rules
        self.rules = rules

    def set_advance_area(self, rect: Rect | None) -> None:
        """Apply rules only inside ``rect``; outside is frozen and invisible to the inside."""
        if rect is not None and rect.wraps and self.edges == "bounded":
            raise ValueError("with bounded edges an advance area cannot cross the plane's edge")
        self.advance_area = rect

    # -- cells ----------------------------------------------------------------
    @property
    def population(self) -> int:
        return self.universe.population()

    @property
    def dense_window(self) -> tuple[int, int, np.ndarray] | None:
        """(top row, left column, uint8 grid of life-forms) while the state is a dense
        grid (read only), else None."""
        return self.universe.window()

    def cells(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(x, y, type) arrays of every live cell, row by row."""
        return self.xs.copy(), self.ys.copy(), self.ts.copy()

    def set_cells(self, xs: Iterable[int] | np.ndarray, ys: Iterable[int] | np.ndarray,
                  ts: Iterable[int] | np.ndarray) -> None:
        """Write many cells at once (type 0 erases); later entries win."""
        nx = np.asarray(xs, np.int64).ravel()
        ny = np.asarray(ys, np.int64).ravel()
        nt = np.broadcast_to(np.asarray(ts, np.int64), nx.shape).ravel()
        if not (nx.shape == ny.shape):
            raise ValueError("xs and ys differ in length")
        if nx.size == 0:
            return
        if nx.min() < 0 or ny.min() < 0 or nx.max() >= SIDE or ny.max() >= SIDE:
            raise ValueError(f"cell position outside the {SIDE}x{SIDE} plane")
        if nt.min() < 0:
            raise ValueError("life-form numbers are >= 0")
        new_keys = ny * SIDE + nx
        if self.population == 0 and bool(np.all(new_keys[1:] > new_keys[:-1])):
            # an empty plane and cells already in row order, each once (a pattern file's):
            # nothing to merge, so no sort or set operations over millions of cells
            live = nt > 0
            self.ts, self.ys, self.xs = nt[live].copy(), ny[live].copy(), nx[live].copy()
            return
        old_keys = self.ys * SIDE + self.xs
        # Last write of each key wins: unique over the reversed list.
        rk, first = np.unique(new_keys[::-1], return_index=True)
        rt = nt[::-1][first]
        keep = ~np.isin(old_keys, rk)
        keys = np.concatenate([old_keys[keep], rk[rt > 0]])
        types = np.concatenate([self.ts[keep], rt[rt > 0]])
        order = np.argsort(keys, kind="stable")
        keys = keys[order]
        self.ts = types[order]
        self.ys = keys // SIDE
        self.xs = keys - self.ys * SIDE

    def set_grid(self, left: int, top: int, grid: np.ndarray) -> None:
        """Replace the plane's cells by a uint8 grid of life-forms whose top-left cell goes
        to (left, top), not crossing the plane's edge.  Rules that can take the dense path
        start from the grid itself (a byte a cell, no cell list made); others get cells."""
        h, w = grid.shape
        if left < 0 or top < 0 or left + w > SIDE or top + h > SIDE:
            raise ValueError(f"a {w}x{h} grid at {left},{top} leaves the {SIDE}x{SIDE} plane")
        self.clear()
        plan = compile_rules(self.rules).dense if self.rules is not None else None
        if plan is not None:
            t = compile_rules(self.rules)
            pad_y, pad_x = t.reach_y + DENSE_MARGIN, t.reach_x + DENSE_MARGIN
            y0, x0 = top - pad_y, left - pad_x
            if y0 >= 0 and x0 >= 0 and top + h + pad_y <= SIDE and left + w + pad_x <= SIDE:
                window = np.zeros((h + 2 * pad_y, w + 2 * pad_x), np.uint8)
                window[pad_y:pad_y + h, pad_x:pad_x + w] = grid
                self.universe = DenseGrid(y0, x0, window, int(np.count_nonzero(grid)))
                return
        ys, xs = np.nonzero(grid)
        self.ts = grid[ys, xs].astype(np.int64)
        self.ys = ys.astype(np.int64) + top
        self.xs = xs.astype(np.int64) + left

    def set(self, x: int, y: int, value: int) -> None:
        """Edit one cell (0 = dead)."""
        self.set_cells([x], [y], [value])

    def get(self, x: int, y: int) -> int:
        keys = self.ys * SIDE + self.xs
        key = y * SIDE + x
        i = int(np.searchsorted(keys, key))
        if i < keys.shape[0] and keys[i] == key:
            return int(self.ts[i])
        return 0

    def _in_rect(self, rect: Rect) -> np.ndarray:
        return rect.contains(self.xs, self.ys)

    def cells_in_rect(self, rect: Rect) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(x, y, type) of live cells inside ``rect`` (which may cross the seam)."""
        if rect.wraps:
            found = [self._cells_in_plain_rect(r) for r in rect.parts()]
            return tuple(np.concatenate(a) for a in zip(*found))
        return self._cells_in_plain_rect(rect)

    def _cells_in_plain_rect(self, rect: Rect) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Rows located by binary search (the rectangle does not cross the seam)."""
        keys = self.ys * SIDE + self.xs
        lo = int(np.searchsorted(keys, rect.y0 * SIDE + rect.x0))
        hi = int(np.searchsorted(keys, rect.y1 * SIDE + rect.x1, side="right"))
        xs, ys, ts = self.xs[lo:hi], self.ys[lo:hi], self.ts[lo:hi]
        m = (xs >= rect.x0) & (xs <= rect.x1)
        return xs[m], ys[m], ts[m]

    def clear(self, rect: Rect | None = None) -> None:
        """Remove every life-form (in ``rect``, or everywhere)."""
        if rect is None:
            self.universe = CellList()  # nothing to convert: all goes
            return
        keep = ~self._in_rect(rect)
        self.ys, self.xs, self.ts = self.ys[keep], self.xs[keep], self.ts[keep]

    def density(self, x0: int, y0: int, cells_per_pixel: int, width: int,
                height: int) -> np.ndarray:
        """Live-cell counts per pixel, each pixel ``cells_per_pixel`` cells square (subpixel
        zoom); pixel (0, 0) starts at cell (x0, y0); the view wraps round the plane."""
        k = int(cells_per_pixel)
        if k < 1:
            raise ValueError("cells_per_pixel must be >= 1")
        px = ((self.xs - x0) % SIDE) // k
        py = ((self.ys - y0) % SIDE) // k
        m = (px < width) & (py < height)
        out = np.zeros(height * width, np.int64)
        np.add.at(out, py[m] * width + px[m], 1)
        return out.reshape(height, width)

    # -- statistics -------------------------------------------------------------
    def by_type(self) -> dict[int, int]:
        return self.universe.by_type(self.rules.max_form if self.rules is not None else 0)

    def bbox(self) -> Rect | None:
        """Smallest rectangle holding every live cell.  On the wrapping plane each axis is
        the smallest interval round the circle (it crosses the seam, x0 > x1, when that is
        shorter); with bounded edges plain minimum and maximum."""
        if self.population == 0:
            return None
        xs, ys = self.universe.occupied()  # read from the tree or grid, no list made
        if self.edges == "bounded":
            return Rect(int(xs.min()), int(ys.min()), int(xs.max()), int(ys.max()))
        x0, x1 = _wrapped_interval(xs)
        y0, y1 = _wrapped_interval(ys)
        return Rect(x0, y0, x1, y1)

    def stats(self) -> dict:
        box = self.bbox()
        return {
            "generation": self.generation,
            "population": self.population,
            "by_type": {str(k): v for k, v in self.by_type().items()},
            "bbox": None if box is None else [box.x0, box.y0, box.x1, box.y1],
        }

    # -- stepping ----------------------------------------------------------------
    def step(self, generations: int = 1, progress: algorithms.Progress | None = None) -> None:
        """Advance ``generations`` with the chosen algorithm; ``progress(done, asked)`` is
        called on the way (after each jump, or each generation)."""
        name = algorithms.choose_engine(self.rules, int(generations), self.advance_area,
                                        self.algorithm, self.algorithm == "auto"
                                        and self.is_dense())
        algorithms.get_algorithm(name).advance(self, int(generations), progress)

    def is_dense(self) -> bool:
        """At least 1/DENSE_MIN_FILL of the live cells' box is alive (cells listed, not a
        tree), as when the dense path runs."""
        u = self.universe
        if isinstance(u, DenseGrid):
            return True
        return isinstance(u, CellList) and u.is_dense(DENSE_MIN_FILL)

    def step_direct(self, generations: int = 1,
                    progress: algorithms.Progress | None = None) -> None:
        """Advance one generation at a time by message passing (the direct algorithm)."""
        if not isinstance(self.universe, DenseGrid):  # a dense grid stays one
            self._list()
        for i in range(int(generations)):
            self._step_once()
            if progress is not None:
                progress(i + 1, int(generations))

    def _step_once(self) -> None:
        if self.rules is None:
            raise RuntimeError("no rules loaded")
        area = self.advance_area
        if area is not None and area.wraps:
            self._step_across_seam(area)
            return
        t = compile_rules(self.rules)
        if self._try_dense(t):
            self.generation += 1
            return
        from camlab88.apps.ca import (
            kernels,  # on the direct engine's first step: a jump never loads it
        )

        self._list()
        area = self.advance_area
        if area is None or area == FULL:
            ys, xs, ts = self.ys, self.xs, self.ts
            frozen = None
            clip = FULL
        else:
            inside = self._in_rect(area)
            ys, xs, ts = self.ys[inside], self.xs[inside], self.ts[inside]
            frozen = ~inside
            clip = area
        bops, bvals = kernels.broadcasts(ts, t.bcast_op, t.bcast_val)
        common = (t.send_start, t.send_dy, t.send_dx, t.send_op, t.send_val, bops, bvals,
                  t.lookup, t.interp_kind, t.interp_a, t.interp_b, t.out_start, t.out_thresh,
                  t.out_form, self.generation, self.seed)
        n = ys.shape[0]
        if n == 0:
            ny = nx = nt = np.zeros(0, np.int64)
        else:
            sends = n * t.sends_per_cell
            y0 = int(ys[0]) - t.reach_y
            y1 = int(ys[-1]) + t.reach_y
            x0 = int(xs.min()) - t.reach_x
            x1 = int(xs.max()) + t.reach_x
            inside_plane = y0 >= 0 and x0 >= 0 and y1 < SIDE and x1 < SIDE
            if self.edges == "bounded" or inside_plane:
                y0, x0 = max(y0, clip.y0), max(x0, clip.x0)
                y1, x1 = min(y1, clip.y1), min(x1, clip.x1)
            area_cells = max(0, y1 - y0 + 1) * max(0, x1 - x0 + 1)
            window_ok = (inside_plane or self.edges == "bounded") and area_cells <= min(
                WINDOW_MAX, WINDOW_MIN + WINDOW_CELLS_PER_SENDER * sends)
            if area_cells == 0:
                ny = nx = nt = np.zeros(0, np.int64)
            elif window_ok:
                self.last_kernel = "window"
                ny, nx, nt = kernels.step_window(
                    ys, xs, ts, y0, x0, y1 - y0 + 1, x1 - x0 + 1, *common,
                    min(area_cells, sends))
            else:
                self.last_kernel = "hash"
                table, order = self._hash_scratch(sends)
                ny, nx, nt = kernels.step_hash(
                    ys, xs, ts, self.edges == "wrap", clip.y0, clip.y1, clip.x0, clip.x1,
                    *common, table, order)
        if frozen is not None and frozen.any():
            ny, nx, nt = _sorted(np.concatenate([ny, self.ys[frozen]]),
                                 np.concatenate([nx, self.xs[frozen]]),
                                 np.concatenate([nt, self.ts[frozen]]))
        self.ys, self.xs, self.ts = ny, nx, nt
        self.generation += 1

    def _step_across_seam(self, area: Rect) -> None:
        """An advance area crossing the seam (wrapping plane only): the plane is a torus, so
        move the area's corner to (0, 0), step, and move back.  (Section 8.1's random
        outcomes hash the shifted positions there: still deterministic.)"""
        ox, oy = area.x0, area.y0
        self._shift(-ox, -oy)
        self.advance_area = Rect(0, 0, area.width - 1, area.height - 1)
        try:
            self._step_once()
        finally:
            self.advance_area = area
            self._shift(ox, oy)

    def _shift(self, dx: int, dy: int) -> None:
        self.universe = CellList(*_sorted((self.ys + dy) % SIDE, (self.xs + dx) % SIDE,
                                          self.ts))

    def _hash_scratch(self, sends: int) -> tuple[np.ndarray, np.ndarray]:
        """Hash table scratch space (kept empty between generations), at least twice the
        messages sent; reallocated only when it must grow."""
        cap = 1024
        while cap < 2 * sends + 16:
            cap *= 2
        if self._hash is None or self._hash[0].shape[0] < cap:
            table = np.empty((cap, 2), np.int64)
            table[:, 0] = -1
            self._hash = (table, np.empty(cap, np.int64))
        return self._hash

    # -- dense fast path ------------------------------------------------------------
    def _try_dense(self, t) -> bool:
        """Step as dense grid passes when the rules allow it and the population is dense."""
        from camlab88.apps.ca import kernels

        plan = t.dense
        if plan is None or (self.advance_area is not None and self.advance_area != FULL):
            return False
        my, mx = t.reach_y, t.reach_x
        u = self.universe
        if isinstance(u, DenseGrid):
            h, w = u.grid.shape
            g = u.grid
            edge = (g[:my].any() or g[h - my:].any() or g[:, :mx].any()
                    or g[:, w - mx:].any()) if (my or mx) else False
            if u.pop * DENSE_MIN_FILL < h * w:
                self._list()  # too sparse: leave the window
            elif edge and not self._grow_dense(my, mx):
                self._list()  # cannot grow in place: rebuild from the cells
        if not isinstance(self.universe, DenseGrid) and not self._enter_dense(my, mx):
            return False
        u = self.universe
        grid = u.grid
        # Reuse the output grid between generations: fresh pages cost more than reuse.
        out, acc = self._buffers if self._buffers is not None else (None, None)
        if out is None or out.shape != grid.shape or acc.dtype != plan.msg_dtype:
            out = np.empty_like(grid)
            acc = np.zeros(grid.shape[1], plan.msg_dtype)
        sep = plan.sep
        if DENSE_SEPARABLE and sep is not None:
            pop = int(kernels.dense_step_separable(
                grid, out, sep.gtype, sep.gval, sep.gy0, sep.gy1, sep.gx0, sep.gx1, sep.xg,
                sep.xdy, sep.xdx, sep.etype, sep.edy, sep.edx, sep.eop, sep.evals, sep.interp,
                plan.lut, sep.masks32, sep.masks64, sep.mforms, acc,
                *self._separable_scratch(sep, grid.shape[1], plan.msg_dtype)))
        else:
            pop = int(kernels.dense_step(grid, out, plan.etype, plan.edy, plan.edx, plan.eop,
                                         plan.evals, plan.lut, acc))
        self.universe = DenseGrid(u.y0, u.x0, out, pop)
        self._buffers = (grid, acc)  # the old grid becomes the next output buffer
        self.last_kernel = "dense"
        return True

    def _enter_dense(self, my: int, mx: int) -> bool:
        """Turn the cell list into a dense window if it is dense enough and fits."""
        cl = self._list()
        n = cl.ts.shape[0]
        if n == 0 or int(cl.ts.max()) > 255:
            return False
        pad_y, pad_x = my + DENSE_MARGIN, mx + DENSE_MARGIN
        y0 = int(cl.ys[0]) - pad_y
        y1 = int(cl.ys[-1]) + pad_y
        x0 = int(cl.xs.min()) - pad_x
        x1 = int(cl.xs.max()) + pad_x
        area_cells = (y1 - y0 + 1) * (x1 - x0 + 1)
        if (y0 < 0 or x0 < 0 or y1 >= SIDE or x1 >= SIDE or area_cells > WINDOW_MAX
                or n * DENSE_MIN_FILL < area_cells):
            return False
        grid = np.zeros((y1 - y0 + 1, x1 - x0 + 1), np.uint8)
        grid[cl.ys - y0, cl.xs - x0] = cl.ts
        self.universe = DenseGrid(y0, x0, grid, n)
        return True

    def _grow_dense(self, my: int, mx: int) -> bool:
        """Widen the dense window by the margin on each side where cells came within the
        message reach of its border, copying the grid (cheaper than rebuilding it from the
        cell list); False if the wider window would leave the plane or get too sparse."""
        u = self.universe
        y0, x0, grid = u.y0, u.x0, u.grid
        h, w = grid.shape
        top = DENSE_MARGIN if my and grid[:my].any() else 0
        bottom = DENSE_MARGIN if my and grid[h - my:].any() else 0
        left = DENSE_MARGIN if mx and grid[:, :mx].any() else 0
        right = DENSE_MARGIN if mx and grid[:, w - mx:].any() else 0
        nh, nw = h + top + bottom, w + left + right
        if (y0 - top < 0 or x0 - left < 0 or y0 - top + nh > SIDE or x0 - left + nw > SIDE
                or nh * nw > WINDOW_MAX or u.pop * DENSE_MIN_FILL < nh * nw):
            return False
        bigger = np.zeros((nh, nw), np.uint8)
        bigger[top:top + h, left:left + w] = grid
        self.universe = DenseGrid(y0 - top, x0 - left, bigger, u.pop)
        return True

    def _separable_scratch(self, sep, w: int, dtype: type) -> tuple[np.ndarray, ...]:
        """Row rings of the separable kernel (indicator rows, horizontal sums, vertical sums),
        kept between generations while their shapes fit."""
        g = sep.gtype.shape[0]
        pad = int((sep.gx1 - sep.gx0).max()) if g else 0
        shapes = ((g, sep.ring, w + pad), (g, sep.ring, w), (g, w))
        have = self._sep_scratch
        if have is None or any(a.shape != s or a.dtype != dtype for a, s in zip(have, shapes)):
            have = tuple(np.zeros(s, dtype) for s in shapes)
            self._sep_scratch = have
        return have

    # -- copies -------------------------------------------------------------------
    def copy(self) -> Engine:
        e = Engine(self.rules, self.edges, self.seed, self.algorithm)
        e.generation = self.generation
        e.advance_area = self.advance_area
        e.hashlife_memory = self.hashlife_memory
        if self.tree is not None:
            e.universe = self.tree  # nodes are immutable: the copy may share the tree
        else:  # a dense grid's buffer is reused by the next step: the copy gets a list
            ys, xs, ts = self.universe.cells()
            e.universe = CellList(ys.copy(), xs.copy(), ts.copy())
        return e

    def same_state(self, other: Engine) -> bool:
        return (self.generation == other.generation
                and np.array_equal(self.ys, other.ys) and np.array_equal(self.xs, other.xs)
                and np.array_equal(self.ts, other.ts))
