"""How fast a host writing flat out gets through: the ``sigma_pty`` fixture and
``sigma run --headless --pty`` (chars/s, and the multiple of the 9600-baud line).

Run by hand: ``python benchmarks/bench_sigma_pty.py [REPEATS]``. A separate process (the
host) writes a real PGPLOT /GOC stream (tests/data/link/pgplot_goctest.goc, 7,670 bytes)
REPEATS times into the pty as fast as the pty takes it; the figure is bytes / wall seconds
from the first write until the terminal has decoded the last byte (``wait_idle`` with a
quiet period of 0, so it is not counted), and that over 960 chars/s (9600 baud 8N1) is the
multiple of the line.  ``sigma run`` is timed from the first write to its exit with
``--until-idle 1`` (the 1 s of idle line time, which follows the wall clock, subtracted),
and its CPU seconds (start-up included) are given too: on a shared machine the wall figure
is mostly the others' load.  The target is >= 100x (issue 42); docs/api.md ("What paces
what") has figures.
"""

from __future__ import annotations

import os
import resource
import subprocess
import sys
import time
from pathlib import Path

from camlab88.bench.pty_sigma import PtySigma

STREAM = Path(__file__).resolve().parents[1] / "tests" / "data" / "link" / "pgplot_goctest.goc"
WRITER = """
import os, sys
fd = os.open(sys.argv[1], os.O_WRONLY | os.O_NOCTTY)
data = open(sys.argv[2], "rb").read() * int(sys.argv[3])
view = memoryview(data)
while view:
    view = view[os.write(fd, view):]
"""
LINE_CPS = 960


def bench(repeats: int = 30, trace: bool = True) -> tuple[int, float, float]:
    """(bytes, wall s, virtual s of line time) for ``repeats`` copies of the stream."""
    bench = PtySigma(trace=trace)
    try:
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", WRITER, bench.path, str(STREAM), str(repeats)],
                       check=True, timeout=600)
        bench.wait_idle(quiet=0.0, timeout=600)
        wall = time.perf_counter() - t0
        n = bench.sigma.stats["bytes"]
        return n, wall, bench.sigma.now
    finally:
        bench.close()


def bench_sigma_run(repeats: int = 30) -> tuple[int, float, float]:
    """(bytes, wall s from the first write to the end minus the idle second, CPU s)."""
    data = STREAM.read_bytes() * repeats
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    run = subprocess.Popen([sys.executable, "-m", "camlab88", "sigma", "run", "--headless",
                            "--pty", "--until-idle", "1"], stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True)
    first = run.stdout.readline()
    t0 = time.perf_counter()
    fd = os.open(first.split()[-1], os.O_WRONLY | os.O_NOCTTY)
    try:
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view):]
        out, err = run.communicate(timeout=600)
    finally:
        os.close(fd)
    wall = time.perf_counter() - t0 - 1.0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    assert f"{len(data)} bytes in" in out, out + err
    return len(data), wall, (r1.ru_utime + r1.ru_stime) - (r0.ru_utime + r0.ru_stime)


def main() -> None:
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 30
    bench(1)  # compile the raster kernels once, outside the figures
    for trace in (True, False):
        n, wall, virtual = bench(repeats, trace)
        print(f"sigma_pty (trace={trace}), host writing flat out: {n} bytes in {wall:.2f} s "
              f"wall ({virtual:.1f} s of line time): {n / wall:,.0f} chars/s = "
              f"{n / wall / LINE_CPS:.0f}x the 9600-baud line")
    n, wall, cpu = bench_sigma_run(repeats)
    print(f"sigma run --headless --pty: {n} bytes in {wall:.2f} s wall: {n / wall:,.0f} "
          f"chars/s = {n / wall / LINE_CPS:.0f}x; {cpu:.2f} s CPU (start-up included): "
          f"{n / cpu / LINE_CPS:.0f}x per CPU second")


if __name__ == "__main__":
    main()
