"""Benchmark beside Golly's bgolly, whole processes (run by hand from the repository:
PYTHONPATH=. python benchmarks/bench_golly.py).

The same pattern files, the same generations, run by ``bgolly`` (Golly 3.3's command-line
program, HashLife: ``-h`` for Life, ``-a RuleLoader`` with the rule table for WireWorld and
Langton's loops) and by ``camlab88 ca run --engine hashlife`` with our rule sets written in
the thesis's rule language. The multi-state rules run at a short jump (start-up bound: bgolly
starts in ~0.01 s, a Python process with numpy and numba in ~0.35 s) and at long ones, where
the pattern's evolution is the work. Each figure: the minimum of RUNS processes' CPU time (user +
system of the child), its wall time, and the child's peak resident memory (GNU time's %M),
start-up included. bgolly is found as the tests find it (tests/ca/golly_oracle.py):
$CAMLAB88_BGOLLY, /opt/golly/usr/bin/bgolly (.ci/run unpacks it there), PATH.
"""

from __future__ import annotations

import os
import resource
import subprocess
import sys
import time
from pathlib import Path

from apps.ca.library import pattern_path
from tests.ca.golly_oracle import DATA, bgolly

HERE = Path(__file__).parent
RUNS = 3
# (label, pattern file, our rule set, generations, bgolly's algorithm arguments)
CASES = [
    ("WireWorld primes", DATA / "primes.mc", "wireworld", 100_000,
     ["-a", "RuleLoader", "-s", f"{DATA}/"]),
    ("WireWorld primes", DATA / "primes.mc", "wireworld", 1_000_000,
     ["-a", "RuleLoader", "-s", f"{DATA}/"]),
    ("Langton's loop", DATA / "Langtons-Loops.rle", "langtons_loops", 2_000,
     ["-a", "RuleLoader", "-s", f"{DATA}/"]),
    # Longer jumps, where the colony (2.7 M and 70 M cells) is the work, not start-up.
    ("Langton's loop", DATA / "Langtons-Loops.rle", "langtons_loops", 20_000,
     ["-a", "RuleLoader", "-s", f"{DATA}/"]),
    ("Langton's loop", DATA / "Langtons-Loops.rle", "langtons_loops", 100_000,
     ["-a", "RuleLoader", "-s", f"{DATA}/"]),
    ("acorn", Path(pattern_path("acorn")), "life", 5206, ["-h"]),
    ("Gosper gun", Path(pattern_path("gosper_gun")), "life", 100_000, ["-h"]),
    ("puffer train", HERE / "patterns" / "puffer_train.rle", "life", 30_000, ["-h"]),
]


def load() -> str:
    return f"load {os.getloadavg()[0]:.2f}"


def timed(cmd: list[str]) -> tuple[float, float, float, str]:
    """(CPU s, wall s, peak MB, stdout) of one child process."""
    timer = ["/usr/bin/time", "-f", "%M"] if Path("/usr/bin/time").exists() else []
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    run = subprocess.run([*timer, *cmd], capture_output=True, text=True, check=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    peak = int(run.stderr.split()[-1]) / 1024 if timer else float("nan")
    return cpu, wall, peak, run.stdout


def best(cmd: list[str]) -> tuple[float, float, float, str]:
    return min((timed(cmd) for _ in range(RUNS)), key=lambda r: r[0])


def main() -> None:
    exe = bgolly()
    if exe is None:
        print("bgolly not found (see tests/ca/golly_oracle.py)")
        return
    ours_exe = str(Path(sys.executable).with_name("camlab88"))
    print(time.strftime("%Y-%m-%d %H:%M"), f"{os.cpu_count()} cores, {load()}")
    totals = {"life": [0.0, 0.0]}
    for label, path, rules, gens, algo in CASES:
        g = best([exe, "-m", str(gens), "-i", str(gens), *algo, str(path)])
        o = best([ours_exe, "ca", "run", "--rules", rules, "--pattern", str(path),
                  "--generations", str(gens), "--engine", "hashlife"])
        gpop = g[3].strip().splitlines()[-1].split(":")[-1].strip().replace(",", "")
        opop = o[3].split("population")[1].split()[0]
        same = "same population" if gpop == opop else f"POPULATIONS DIFFER {gpop} {opop}"
        print(f"{label:16} {gens:>8,} gens: bgolly {g[0]:.2f} s CPU ({g[1]:.2f} wall, "
              f"{g[2]:.0f} MB)  ours {o[0]:.2f} s CPU ({o[1]:.2f} wall, {o[2]:.0f} MB)  "
              f"ratio {o[0] / max(g[0], 1e-3):.1f}x  {same}  {load()}")
        if rules == "life":
            totals["life"][0] += g[0]
            totals["life"][1] += o[0]
    g, o = totals["life"]
    print(f"three Life processes: bgolly {g:.2f} s CPU, ours {o:.2f} s CPU, ratio "
          f"{o / max(g, 1e-3):.1f}x")


if __name__ == "__main__":
    main()
