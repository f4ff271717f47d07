"""KAS benchmarks: in-betweening 250 frames of two 10,000-point keyframes (target <= 0.5 s).

Run: python benchmarks/bench_kas.py   (prints the figures; docs/perf/kas.md records them)
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from _bench import times

from camlab88.apps.kas import files, timing
from camlab88.apps.kas.files import SamplePath
from camlab88.apps.kas.inbetween import inbetween, inbetween_keys
from camlab88.apps.kas.model import Chain, Drawing


def keyframe(seed: int, chains: int, total: int) -> Drawing:
    """``chains`` wiggly chains with ``total`` points in all (no collinear runs)."""
    rng = np.random.default_rng(seed)
    per = total // chains
    out = []
    for j in range(chains):
        t = np.linspace(0, 1, per)
        x = -5 + 10 * t + 0.05 * rng.standard_normal(per)
        y = -4 + 8 * j / chains + 0.3 * np.sin(t * 20 + seed) + 0.05 * rng.standard_normal(per)
        out.append(Chain.from_points(np.column_stack([x, y]), 1 + j % 8, j // 10))
    return Drawing(out)


def best(fn, repeat: int = 5) -> float:
    return min(times(fn, repeat))


def main() -> None:
    path = SamplePath(np.column_stack([np.linspace(0, 6, 60), np.sin(np.linspace(0, 3, 60))]))
    ticks = timing.ticks_from_curve(timing.curve("ease-in-out"), 250)
    rows = []
    for chains in (1, 100):
        a = keyframe(1, chains, 10_000)
        b = keyframe(2, chains, 10_000)
        b_uneven = keyframe(3, chains, 9_000)  # forces resampling of every chain
        rows.append((f"2 keys x 10,000 pts in {chains} chain(s), straight, 250 frames",
                     best(lambda a=a, b=b: inbetween(a, b, 250))))
        rows.append(("  same with hand path + tick timing (fit=stretch)",
                     best(lambda a=a, b=b: inbetween(a, b, path=path, timing=ticks))))
        rows.append(("  same, 9,000-pt second key (resampled), ease curve",
                     best(lambda a=a, b=b_uneven: inbetween(
                         a, b, 250, timing=timing.curve("ease-in-out")))))
    a, b, c = (keyframe(s, 100, 10_000) for s in (1, 2, 3))
    rows.append(("3 keys x 10,000 pts, Catmull-Rom, 2 x 125 frames",
                 best(lambda: inbetween_keys([a, b, c], 126, "catmull-rom"))))
    rows.append(("3 keys x 10,000 pts, Overhauser, 2 x 125 frames",
                 best(lambda: inbetween_keys([a, b, c], 126, "overhauser"))))
    seq = inbetween(a, b, 250)
    with tempfile.TemporaryDirectory() as d:
        f = Path(d) / "s.kas"
        rows.append(("save 250-frame sequence (2.5 M points)",
                     best(lambda: files.save_sequence(f, seq), 1)))
        rows.append(("load it back", best(lambda: files.load_sequence(f), 1)))
        size = f.stat().st_size
    code = ("import time; t = time.perf_counter(); "
            "from camlab88.apps.kas.model import Chain, Drawing; "
            "from camlab88.apps.kas.inbetween import inbetween; "
            "d = Drawing([Chain.from_points([(0, 0), (1, 1), (2, 0)])]); inbetween(d, d, 3); "
            "print(time.perf_counter() - t)")
    first = float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                 check=True).stdout)
    rows.append(("first tiny in-between in a fresh process (imports, numba cache)", first))
    print("KAS benchmarks (best of 5; file I/O once)")
    for name, secs in rows:
        print(f"  {name:58} {secs * 1000:8.1f} ms")
    print(f"  sequence file size: {size / 1e6:.1f} MB")


if __name__ == "__main__":
    main()
