"""Snooker renderer benchmarks (issue 13): truecolour frame time, the period/fixed modes'
line time and wall time through the emulated T5688, and the palette table.

Run: .venv/bin/python benchmarks/bench_render.py [--quick]
(figures go to docs/perf/render.md by hand; the load average is printed beside them)
"""

from __future__ import annotations

import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from apps.snooker.render.metrics import score  # noqa: E402
from apps.snooker.render.palette import adaptive_palette, fixed_palette  # noqa: E402
from apps.snooker.render.sigma_host import SigmaHost  # noqa: E402
from apps.snooker.render.sigma_session import SigmaSession  # noqa: E402
from apps.snooker.render.truecolour import RenderOptions, render_frame, render_linear  # noqa: E402
from emulator.sigma import Terminal  # noqa: E402
from tests.snooker_render.helpers import break_scene, break_views  # noqa: E402


def load() -> str:
    a, b, c = os.getloadavg()
    return f"load average {a:.2f} {b:.2f} {c:.2f}"


def timed(fn, repeat: int) -> tuple[float, float]:  # noqa: ANN001
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return min(times), statistics.median(times)


def bench_truecolour(repeat: int) -> None:
    scene, view = break_scene(), break_views()[0]
    assert scene.on_table[0].sum() == 22
    opts = RenderOptions(768, 512)
    render_frame(scene, view, opts)  # compile / load the kernels
    lo, med = timed(lambda: render_frame(scene, view, opts), repeat)
    print(f"truecolour 768x512, 22 balls, {len(scene.lights.positions)} lights, shadows, AA, "
          f"specks: min {lo * 1e3:.1f} ms, median {med * 1e3:.1f} ms ({repeat} runs; {load()})")


def bench_sigma(frames: list[int]) -> None:
    scene, views = break_scene(), break_views()
    pal = fixed_palette(scene)
    for mode in ("period", "fixed"):
        term = Terminal("t5688")
        session = SigmaSession(SigmaHost(scene, pal, mode), term)
        for f in frames:
            t = time.perf_counter()
            sent = session.show(views[f - 1])
            wall = time.perf_counter() - t
            kinds = ", ".join(f"{k} {v}" for k, v in sent.frame.bytes_by_kind.items())
            print(f"{mode} frame {f}: {len(sent.frame.data)} bytes = {sent.line_seconds:.1f} s "
                  f"at 9600 baud; wall {wall:.2f} s through the emulator; leaks {sent.leaks}, "
                  f"gaps {sent.gaps} ({kinds}; {load()})")


def bench_palette(step: int) -> None:
    scene = break_scene()
    views = break_views()[::step]
    frames = [render_linear(scene, v) for v in views]
    t = time.perf_counter()
    adaptive = adaptive_palette(frames)
    choose = time.perf_counter() - t
    rows = [("fixed (period)", score(frames, [fixed_palette(scene)])),
            ("adaptive, one for the sequence", score(frames, [adaptive])),
            ("adaptive, chosen per frame", score(frames, [adaptive_palette([f])
                                                          for f in frames]))]
    print(f"palette over {len(frames)} frames of the break at 768x512 (k-means {choose:.1f} s; "
          f"{load()}):")
    print("| palette | mean dE (error) | flicker (mean dE, still pixels) |")
    print("|---|---|---|")
    for name, s in rows:
        print(f"| {name} | {s.error:.4f} | {s.flicker:.5f} |")
    print(f"adaptive / fixed error: {rows[1][1].error / rows[0][1].error:.2f}")


def main() -> None:
    quick = "--quick" in sys.argv
    if "--truecolour" in sys.argv:
        bench_truecolour(30)
        return
    print(f"numpy {np.__version__}; {os.cpu_count()} CPUs; {load()}")
    bench_truecolour(5 if quick else 30)
    bench_sigma([1, 20] if quick else [1, 12, 20, 40])
    bench_palette(8 if quick else 1)


if __name__ == "__main__":
    main()
