"""Rainbow benchmarks: compile time against number of pads, and frames/s with 64 pads moving.

Run by hand: ``python benchmarks/bench_rainbow.py``. Prints a Markdown table of figures.
"""

from __future__ import annotations

import platform
import statistics

import numpy as np
from _bench import rate, times

from camlab88.emulator.machine import RainbowMachine
from camlab88.emulator.rainbow import Rainbow
from camlab88.emulator.rainbow.compiler import Compiler


def scene(n: int, seed: int = 0) -> tuple[Rainbow, list[int]]:
    rng = np.random.default_rng(seed)
    r = Rainbow()
    r.set_lut(0, rng.integers(0, 256, (4096, 3)))
    arcs = []
    pads = [r.create_pad(int(rng.integers(16, 120)), int(rng.integers(16, 120)), 4,
                         plane=int(rng.integers(0, 5)), lut_page=int(rng.integers(0, 16)))
            for _ in range(min(n, 64))]  # 64 distinct pads, mapped to make n instances
    for p in pads:
        r.canvas(p).put(0, 0, rng.integers(0, 16, (r.graph.nodes[p].height,
                                                    r.graph.nodes[p].width)))
    for i in range(n):
        arcs.append(r.map(0, pads[i % len(pads)], int(rng.integers(-50, 760)),
                          int(rng.integers(-50, 570)), int(rng.integers(0, 4))))
    return r, arcs


def timeit(fn, repeat: int) -> float:
    return statistics.median(times(fn, repeat))


def compile_table() -> list[str]:
    rows = ["| mapped pads | bands | spans | full compile (ms) | move one arc, incremental (ms) "
            "| rows rebuilt |", "|---|---|---|---|---|---|"]
    for n in (1, 4, 16, 64, 256, 1024):
        r, arcs = scene(n)
        comp = Compiler()
        full = timeit(lambda r=r: Compiler().compile(r.graph), 7 if n < 1024 else 3)
        s = comp.compile(r.graph)
        rng = np.random.default_rng(1)
        rebuilt = []

        def move_one(r=r, arcs=arcs, comp=comp, rng=rng, rebuilt=rebuilt):
            a = arcs[int(rng.integers(len(arcs)))]
            arc = r.graph.arcs[a]
            r.move(a, arc.x + int(rng.integers(-3, 4)), arc.y + int(rng.integers(-3, 4)))
            comp.compile(r.graph)
            rebuilt.append(comp.stats.last_rows)

        inc = timeit(move_one, 21 if n < 1024 else 7)
        rows.append(f"| {n} | {len(s.bands)} | {len(s.spans)} | {full * 1e3:.2f} | "
                    f"{inc * 1e3:.2f} | {statistics.median(rebuilt):.0f} of 576 |")
    return rows


def fps_lines() -> list[str]:
    out = []
    r, arcs = scene(64, seed=3)
    rng = np.random.default_rng(2)
    vel = rng.integers(-4, 5, (64, 2))
    r.frame()

    def step():
        for a, (dx, dy) in zip(arcs, vel):
            arc = r.graph.arcs[a]
            r.move(a, (arc.x + dx) % 800 - 30, (arc.y + dy) % 600 - 20)
        r.frame()

    for _ in range(20):
        step()
    n = 300
    fps = rate(step, n)
    out.append(f"- 64 pads moving every frame, device API (compile + scan-out): "
               f"**{fps:.0f} frames/s**")
    # the same through the client API and command stream, in process
    s = RainbowMachine()
    c = s.client
    rng = np.random.default_rng(3)
    c.set_lut(0, [tuple(int(v) for v in rng.integers(0, 256, 3)) for _ in range(4096)])
    pads = [c.create_pad(int(rng.integers(16, 120)), int(rng.integers(16, 120)), 4,
                         int(rng.integers(0, 5)), int(rng.integers(0, 16))) for _ in range(64)]
    carcs = [c.map(0, p, int(rng.integers(0, 700)), int(rng.integers(0, 500)),
                   int(rng.integers(0, 4))) for p in pads]
    pos = {a: [int(rng.integers(0, 700)), int(rng.integers(0, 500))] for a in carcs}

    def cstep():
        for a, (dx, dy) in zip(carcs, vel):
            p = pos[a]
            p[0], p[1] = (p[0] + dx) % 800 - 30, (p[1] + dy) % 600 - 20
            c.move(a, p[0], p[1])
        c.wait_frame()

    for _ in range(20):
        cstep()
    fps2 = rate(cstep, n)
    out.append(f"- the same through the client API (65 stream commands a frame, in process): "
               f"**{fps2:.0f} frames/s**")
    # scan-out alone
    scan = timeit(lambda: r.frame(), 50)
    out.append(f"- video processor alone (768x576 frame, nothing changed): {scan * 1e3:.2f} ms")
    return out


def main() -> None:
    # warm the numba kernels (cached on disk after the first run)
    scene(4)[0].frame()
    print(f"# Rainbow benchmark ({platform.machine()}, Python {platform.python_version()})\n")
    print("## Compile time against number of mapped pads\n")
    print("\n".join(compile_table()))
    print("\n## Frames per second\n")
    print("\n".join(fps_lines()))


if __name__ == "__main__":
    main()
