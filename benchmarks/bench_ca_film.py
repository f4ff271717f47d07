"""`ca film` benchmark: Life's glider gun under the chess actors (examples/ca/chess.actors),
768 x 512 truecolour, 2 x 2 samples a pixel, rendered on the local pool (one process per
core) as the command renders it; a sample of frames also in this process for the per-frame
cost of one core.

Run: .venv/bin/python benchmarks/bench_ca_film.py [--generations 60] [--per-generation 8]
     [--sample 6]
(figures go to docs/perf/ca_film.md by hand; the load average is printed beside each)
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import sys
import tempfile
import time
from pathlib import Path

from _bench import ROOT, load

from camlab88.apps.cafilm.build import FilmSpec, build
from camlab88.apps.cafilm.film import render_image, shoot


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--generations", type=int, default=60)
    p.add_argument("--per-generation", type=int, default=8)
    p.add_argument("--sample", type=int, default=6)
    p.add_argument("--workers", type=int, default=None)
    a = p.parse_args()
    spec = FilmSpec("life", "gosper_gun", a.generations,
                    str(ROOT / "examples" / "ca" / "chess.actors"),
                    str(ROOT / "examples" / "ca" / "gun.ccl"), per_generation=a.per_generation)
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}; {load()}")
    t = time.perf_counter()
    film = build(spec)
    print(f"build (rules, pattern, {a.generations} generations, camera): "
          f"{time.perf_counter() - t:.2f} s; {film.n_frames} frames")
    render_image(film, 1)  # compile / load the kernels once here
    picks = [1 + k * (film.n_frames - 1) // max(a.sample - 1, 1) for k in range(a.sample)]
    costs = []
    for n in picks:
        t = time.perf_counter()
        render_image(film, n)
        costs.append(time.perf_counter() - t)
    print(f"one process, frames {picks}: " + ", ".join(f"{c:.2f}" for c in costs)
          + f" s; mean {sum(costs) / len(costs):.2f} s/frame; {load()}")
    out = Path(tempfile.mkdtemp(prefix="bench-ca-film-"))
    try:
        t = time.perf_counter()
        report = shoot(film, out, None, a.workers)
        wall = time.perf_counter() - t
    finally:
        shutil.rmtree(out, ignore_errors=True)
    n = len(report.rendered)
    print(f"local pool ({a.workers or os.cpu_count()} processes): {n} frames in {wall:.1f} s, "
          f"{wall / n:.2f} s/frame wall, {n / wall:.2f} frames/s; {load()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
