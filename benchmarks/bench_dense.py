"""Benchmark of dense patterns (run by hand: python benchmarks/bench_dense.py [--no-process]).

A 4000 x 4000 block of live cells (a 28 KB RLE of rows ``4000o$``) and a random 4000 x 4000
soup (density 0.5, numpy seed 2026; a 12 MB RLE), each through ``ca run --rules life
--generations 3``, direct and HashLife (goal: at most 1 s and 0.5 GB). In process: reading
the RLE, placing it on the engine, the three generations and the statistics, CPU and wall
(best of 3); then the whole ``camlab88 ca run`` process, start-up included, wall, CPU and
peak memory (max RSS of the child). The load average is printed beside each figure: the
machine may be shared.
"""

from __future__ import annotations

import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from camlab88.apps.ca.engine import CENTRE, Engine
from camlab88.apps.ca.library import rules_path
from camlab88.apps.ca.patterns import read_pattern, rle_lines
from camlab88.apps.ca.rules import load_rules

SIDE = 4000
RUNS = 3


def load() -> str:
    return f"load {os.getloadavg()[0]:.2f}"


def block_rle(side: int = SIDE) -> str:
    return f"x = {side}, y = {side}, rule = B3/S23\n" + f"{side}o$\n" * (side - 1) + \
        f"{side}o!\n"


def soup_rle(side: int = SIDE, seed: int = 2026) -> str:
    """A random soup as RLE, lines cut between tokens at 70 columns (as Golly writes)."""
    grid = np.random.default_rng(seed).random((side, side)) < 0.5
    tokens: list[str] = []
    for y, row in enumerate(grid):
        edges = np.flatnonzero(np.diff(row.astype(np.int8))) + 1
        starts = np.r_[0, edges]
        lengths = np.diff(np.r_[starts, side])
        for s, n in zip(starts.tolist(), lengths.tolist()):
            sym = "o" if row[s] else "b"
            tokens.append(f"{n}{sym}" if n > 1 else sym)
        tokens.append("$" if y < side - 1 else "!")
    return f"x = {side}, y = {side}, rule = B3/S23\n" + "\n".join(rle_lines(tokens)) + "\n"


def in_process(path: str, algorithm: str) -> tuple[float, float, dict]:
    rules = load_rules(rules_path("life"))
    best_cpu = best_wall = float("inf")
    for _ in range(RUNS):
        rules._tables.pop("hashlife_bits_run", None)  # an empty node table each run
        c, w = time.process_time(), time.perf_counter()
        p = read_pattern(path)
        e = Engine(rules, algorithm=algorithm)
        grid = p.placed_grid(CENTRE, CENTRE)
        if grid is not None:
            e.set_grid(*grid)
        else:
            e.set_cells(*p.placed(CENTRE, CENTRE))
        e.step(3)
        stats = e.stats()
        best_cpu = min(best_cpu, time.process_time() - c)
        best_wall = min(best_wall, time.perf_counter() - w)
    return best_cpu, best_wall, stats


def whole_process(path: str, algorithm: str, generations: int = 3) -> str:
    """Wall, CPU and peak memory of one ``ca run`` child. The peak is GNU time's (%M): the
    rusage of a child made by fork carries the parent's resident set from before exec."""
    exe = str(Path(sys.executable).with_name("camlab88"))
    timer = ["/usr/bin/time", "-f", "%M"] if Path("/usr/bin/time").exists() else []
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    run = subprocess.run([*timer, exe, "ca", "run", "--rules", "life", "--pattern", path,
                          "--generations", str(generations), "--engine", algorithm],
                         check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    peak = (f"peak RSS {int(run.stderr.split()[-1]) / 1024:.0f} MB" if timer
            else "peak RSS not measured (no /usr/bin/time)")
    return f"{wall:.2f} s wall, {cpu:.2f} s CPU, {peak}"


def main() -> None:
    print(time.strftime("%Y-%m-%d %H:%M"), f"{os.cpu_count()} cores, python "
          f"{sys.version.split()[0]}, {load()}")
    if "--no-process" not in sys.argv:
        print(f"start-up floor (glider, 0 generations): "
              f"{whole_process('glider', 'direct', 0)}   {load()}")
    with tempfile.TemporaryDirectory() as tmp:
        cases = {"block": Path(tmp) / "block.rle", "soup": Path(tmp) / "soup.rle"}
        cases["block"].write_text(block_rle())
        cases["soup"].write_text(soup_rle())
        for name, path in cases.items():
            size = path.stat().st_size
            for algorithm in ("direct", "hashlife"):
                in_process(str(path), algorithm)  # kernels loaded, caches warm
                cpu, wall, stats = in_process(str(path), algorithm)
                print(f"{name:5} ({size / 1e6:5.2f} MB RLE) {algorithm:8}: in process "
                      f"{cpu:.3f} s CPU, {wall:.3f} s wall (best of {RUNS}); population "
                      f"{stats['population']:,} bbox {stats['bbox']}   {load()}")
                if "--no-process" not in sys.argv:
                    print(f"      whole ca run process: {whole_process(str(path), algorithm)}"
                          f"   {load()}")


if __name__ == "__main__":
    main()
