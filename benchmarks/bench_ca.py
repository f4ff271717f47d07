"""Benchmark of the cellular automaton engine (run by hand: python benchmarks/bench_ca.py).

Life written in the rule language (thesis figure 7.6) run by the general message-passing
engine, beside a hand-written numpy Life on the same machine:

* methuselahs (R-pentomino to generation 1103, acorn to 5206) on the sparse 65536^2 plane;
  the numpy Life needs a dense grid big enough for the pattern's final extent, and costs
  the same per generation whatever is on it, so it is timed over fewer generations;
* a dense random 1024 x 1024 area (density 0.5): the engine with bounded edges on the
  plane, numpy on a 1024 x 1024 grid with dead borders (the same until the soup reaches
  the border; the populations after 20 generations are compared).

"cell-updates/s" for the engine counts live cells processed (its work); for the grid it
counts grid cells; "grid-equivalent" for the engine is area x generations / time.
"""

from __future__ import annotations

import platform
import time

import numpy as np

from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules

LIFE = load_rules(rules_path("life"))


class NumpyLife:
    """A straightforward, reasonably tuned numpy Life on a fixed grid with dead borders."""

    def __init__(self, grid: np.ndarray) -> None:
        h, w = grid.shape
        self.a = np.zeros((h + 2, w + 2), np.uint8)
        self.a[1:-1, 1:-1] = grid
        self.n = np.zeros((h, w), np.uint8)

    def step(self) -> None:
        a, n = self.a, self.n
        n[:] = a[:-2, :-2]
        n += a[:-2, 1:-1]
        n += a[:-2, 2:]
        n += a[1:-1, :-2]
        n += a[1:-1, 2:]
        n += a[2:, :-2]
        n += a[2:, 1:-1]
        n += a[2:, 2:]
        c = a[1:-1, 1:-1]
        a[1:-1, 1:-1] = (n == 3) | ((n == 2) & (c == 1))

    @property
    def population(self) -> int:
        return int(self.a.sum())


class FastNumpyLife(NumpyLife):
    """A faster hand-written numpy Life: the 3x3 box sum is separable, so sum each row's
    three neighbours, then three of those row sums down the columns (4 additions instead of
    8); the box includes the cell itself, so birth is 3 and survival is 3 or 4."""

    def __init__(self, grid: np.ndarray) -> None:
        super().__init__(grid)
        h, w = grid.shape
        self.r = np.zeros((h + 2, w), np.uint8)
        self.m = np.zeros((h, w), bool)

    def step(self) -> None:
        a, r, n, m = self.a, self.r, self.n, self.m
        np.add(a[:, :-2], a[:, 1:-1], out=r)
        r += a[:, 2:]
        np.add(r[:-2], r[1:-1], out=n)
        n += r[2:]
        c = a[1:-1, 1:-1]
        np.equal(n, 4, out=m)
        m &= c.view(bool)
        m |= n == 3
        c[:] = m


def _engine_run(xs, ys, gens: int, edges: str = "wrap") -> tuple[float, int, Engine]:
    e = Engine(LIFE, edges=edges)
    e.set_cells(xs, ys, 1)
    warm = e.copy()
    warm.step(2)  # numba compilation happens outside the timing
    soup = Engine(LIFE, edges=edges)  # ... also of the dense path, which the run may reach
    sy, sx = np.nonzero(np.random.default_rng(0).random((48, 48)) < 0.5)
    soup.set_cells(sx + 1000, sy + 1000, 1)
    soup.step(2)
    live = 0
    t0 = time.perf_counter()
    for _ in range(gens):
        live += e.population
        e.step()
    return time.perf_counter() - t0, live, e


def _numpy_run(grid: np.ndarray, gens: int, cls: type[NumpyLife] = NumpyLife,
               ) -> tuple[float, NumpyLife]:
    life = cls(grid)
    life.step()
    life = cls(grid)
    t0 = time.perf_counter()
    for _ in range(gens):
        life.step()
    return time.perf_counter() - t0, life


BASELINES = (("numpy Life (8 adds)", NumpyLife), ("fast numpy Life (4 adds)", FastNumpyLife))


def methuselah(name: str, gens: int, grid_side: int, numpy_gens: int) -> None:
    p = read_pattern(pattern_path(name))
    xs, ys, _ = p.placed(32768, 32768)
    dt, live, e = _engine_run(xs, ys, gens)
    print(f"{name}: engine {gens} generations in {dt:.3f} s = {gens / dt:,.0f} gen/s, "
          f"{live / dt:,.0f} live-cell updates/s, final population {e.population}")
    grid = np.zeros((grid_side, grid_side), np.uint8)
    off = grid_side // 2
    grid[p.ys + off - p.ref[1], p.xs + off - p.ref[0]] = 1
    for label, cls in BASELINES:
        ndt, life = _numpy_run(grid, numpy_gens, cls)
        print(f"{name}: {label} on {grid_side}x{grid_side} (holds the final extent) "
              f"{numpy_gens} generations in {ndt:.3f} s = {numpy_gens / ndt:,.0f} gen/s, "
              f"{grid_side * grid_side * numpy_gens / ndt:,.0f} cell-updates/s")
        print(f"{name}: engine / {label} speed = {(gens / dt) / (numpy_gens / ndt):.2f}x")


def dense(side: int = 1024, gens: int = 100, density: float = 0.5, repeats: int = 3) -> None:
    """Best of ``repeats`` alternating runs each (the machine is shared: best = least
    disturbed)."""
    rng = np.random.default_rng(1987)
    grid = (rng.random((side, side)) < density).astype(np.uint8)
    ys, xs = np.nonzero(grid)
    best_e = float("inf")
    best_n = {label: float("inf") for label, _ in BASELINES}
    for _ in range(repeats):
        dt, live, e = _engine_run(xs + 32768 - side // 2, ys + 32768 - side // 2, gens,
                                  edges="bounded")
        for label, cls in BASELINES:
            ndt, _ = _numpy_run(grid, gens, cls)
            best_n[label] = min(best_n[label], ndt)
        if dt < best_e:
            best_e, best_live, kernel = dt, live, e.last_kernel
    print(f"dense {side}x{side} d={density}: engine {gens} generations best {best_e:.3f} s = "
          f"{gens / best_e:,.1f} gen/s, {best_live / best_e:,.0f} live-cell updates/s, "
          f"{side * side * gens / best_e:,.0f} grid-equivalent cell-updates/s "
          f"(path: {kernel})")
    for label, _ in BASELINES:
        bn = best_n[label]
        print(f"dense {side}x{side}: {label} {gens} generations best {bn:.3f} s = "
              f"{gens / bn:,.1f} gen/s, {side * side * gens / bn:,.0f} cell-updates/s")
        print(f"dense {side}x{side}: engine / {label} speed = {bn / best_e:.2f}x")
    e2 = Engine(LIFE, edges="bounded")
    e2.set_cells(xs + 1000, ys + 1000, 1)
    lives = [cls(np.pad(grid, 64)) for _, cls in BASELINES]
    for _ in range(20):
        e2.step()
        for life in lives:
            life.step()
    pops = [life.population for life in lives]
    print(f"dense {side}x{side}: populations after 20 generations engine {e2.population}, "
          f"numpy {pops} (equal: {all(p == e2.population for p in pops)})")


def main() -> None:
    import numba

    print(f"machine: {platform.machine()} {platform.python_implementation()} "
          f"{platform.python_version()} numpy {np.__version__} numba {numba.__version__} "
          "(all single-threaded)")
    methuselah("r_pentomino", 1103, 640, 300)
    methuselah("acorn", 5206, 2560, 100)
    dense()
    dense(gens=1000, repeats=1)


if __name__ == "__main__":
    main()
