"""Auto-painting a 100-frame sequence with 10 operations through the emulated T5688.

The sequence: the shipped walk in-betweened over 100 frames with the sun rising beside it
(superimposed), 3 line-chains a frame.  Ten operations: selects, a chain coloured, regions.
Measured: wall time of planning + the program's bytes + the 9600-baud line on its virtual
clock + the terminal drawing them (the numba kernels warmed first), and the line time per
frame a 1984 animator would have waited.  Run: .venv/bin/python benchmarks/bench_paint.py
"""

from __future__ import annotations

import os
import statistics
import time

from camlab88.apps.kas import files
from camlab88.apps.kas.inbetween import inbetween
from camlab88.apps.kas.library import LIBRARY
from camlab88.apps.kas.paint.ops import Op, OpsFile
from camlab88.apps.kas.paint.program import Line, PaintProgram
from camlab88.apps.kas.paint.replay import replay
from camlab88.apps.kas.superimpose import superimpose
from camlab88.emulator.sigma import Terminal


def sequence():
    k = files.load_keyframe
    walk = inbetween(k(LIBRARY / "walk_a.kas"), k(LIBRARY / "walk_b.kas"),
                     path=files.load_path(LIBRARY / "walk_path.kas"), frames=100)
    sun = inbetween(k(LIBRARY / "sun_a.kas"), k(LIBRARY / "sun_b.kas"),
                    timing=files.load_timing(LIBRARY / "ease-in-out.kas"), frames=100)
    return superimpose([(walk, 0), (sun, 0)])


def operations(seq) -> OpsFile:
    mid = seq.frames[49]
    sun_c = tuple(mid.chains[2].centre())
    ring = tuple(mid.chains[1].centre())
    ops = [Op("fill", 3, chains=(2,)), Op("fill", 5, chains=(1,)), Op("fill", 4, chains=(3,)),
           Op("region", 6, at=sun_c), Op("region", 7, at=ring), Op("line", 8, chains=(1,)),
           Op("fill", 9, chains=(1, 2)), Op("line", 2, chains=(3,)), Op("fill", 12, chains=(2,)),
           Op("region", 14, at=sun_c)]
    return OpsFile(ops=ops, painted=50)


def run_once(seq, ops) -> tuple[float, float, object]:
    term = Terminal("t5688")
    t, c = time.perf_counter(), time.process_time()
    rep = replay(PaintProgram(seq, ops), Line(term))
    return time.perf_counter() - t, time.process_time() - c, rep


def main() -> None:
    seq = sequence()
    ops = operations(seq)
    run_once(seq, ops)  # warm the numba kernels (and their cache)
    walls, cpus = [], []
    for _ in range(5):
        w, c, rep = run_once(seq, ops)
        walls.append(w)
        cpus.append(c)
        print(f"  {w:.2f} s wall, {c:.2f} s CPU   load average {os.getloadavg()[0]:.2f}")
    print(f"100 frames x 10 operations through the T5688: wall min {min(walls):.2f} s, "
          f"median {statistics.median(walls):.2f} s (goal <= 2 s); CPU min {min(cpus):.2f} s, "
          f"median {statistics.median(cpus):.2f} s")
    print("  " + rep.summary())


if __name__ == "__main__":
    main()
