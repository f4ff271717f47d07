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

``--ab BASE`` compares this tree with another checkout BASE (e.g. a ``git worktree`` of
main) in the same minutes: for each case, PAIRS rounds of base, this tree, bgolly and the
floor (``python -c "import numpy"``; floor1: the same with one BLAS thread, as camlab88
sets it) one after the other, each ours as ``python -m
camlab88`` with PYTHONPATH set to its tree (and BASE's with ``--base-env NAME=VALUE``
settings, e.g. an older tree's own options); medians and minima of CPU and wall.
Byte code is written for both trees (PYTHONDONTWRITEBYTECODE is dropped for the children),
as an installed program has it.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

from camlab88.apps.ca.library import pattern_path
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


def timed(cmd: list[str], env: dict[str, str] | None = None,
          cwd: Path | None = None) -> tuple[float, float, float, str]:
    """(CPU s, wall s, peak MB, stdout) of one child process."""
    timer = ["/usr/bin/time", "-f", "%M"] if Path("/usr/bin/time").exists() else []
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    run = subprocess.run([*timer, *cmd], capture_output=True, text=True, check=True, env=env,
                         cwd=cwd)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    peak = int(run.stderr.split()[-1]) / 1024 if timer else float("nan")
    return cpu, wall, peak, run.stdout


def best(cmd: list[str]) -> tuple[float, float, float, str]:
    return min((timed(cmd) for _ in range(RUNS)), key=lambda r: r[0])


def _tree_env(tree: Path, settings: list[str]) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env["PYTHONPATH"] = str(tree)
    env.update(s.split("=", 1) for s in settings)
    return env


def _summary(name: str, runs: list[tuple[float, float, float, str]]) -> str:
    cpu, wall = [r[0] for r in runs], [r[1] for r in runs]
    return (f"{name} CPU {statistics.median(cpu):.3f} (min {min(cpu):.3f}) wall "
            f"{statistics.median(wall):.3f} (min {min(wall):.3f})")


def ab(base: Path, base_env: list[str], pairs: int, only: str) -> None:
    """This tree against ``base``, with bgolly and the numpy floor, interleaved."""
    exe = bgolly()
    here = HERE.parent
    envs = {"base": _tree_env(base, base_env), "new": _tree_env(here, [])}
    trees = {"base": base, "new": here}  # ``python -m`` puts its directory first on the path
    print(time.strftime("%Y-%m-%d %H:%M"), f"{os.cpu_count()} cores, {load()}, "
          f"{pairs} rounds: base {base}, new {here}")
    for label, path, rules, gens, algo in CASES:
        if only not in f"{label} {gens}":
            continue
        argv = ["-m", "camlab88", "ca", "run", "--rules", rules, "--pattern", str(path),
                "--generations", str(gens), "--engine", "hashlife"]
        runs: dict[str, list] = {"base": [], "new": [], "bgolly": [], "floor": [],
                                 "floor1": []}
        for _ in range(pairs):
            for name in ("base", "new"):
                runs[name].append(timed([sys.executable, *argv], envs[name], trees[name]))
            if exe is not None:
                runs["bgolly"].append(timed([exe, "-m", str(gens), "-i", str(gens), *algo,
                                             str(path)]))
            runs["floor"].append(timed([sys.executable, "-c", "import numpy"], envs["new"]))
            runs["floor1"].append(timed([sys.executable, "-c", "import numpy"],
                                        {**envs["new"], "OPENBLAS_NUM_THREADS": "1"}))
        pops = {runs[n][0][3].split("population")[1].split()[0] for n in ("base", "new")}
        print(f"{label} {gens:,} gens ({load()}; populations {sorted(pops)}):")
        for name, rs in runs.items():
            if rs:
                print("   ", _summary(f"{name:6}", rs))
        if runs["bgolly"]:
            g = statistics.median(r[0] for r in runs["bgolly"])
            for name in ("base", "new"):
                m = statistics.median(r[0] for r in runs[name])
                print(f"    {name} / bgolly (CPU medians) {m / max(g, 1e-3):.1f}x")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ab", type=Path, metavar="BASE", help="compare with checkout BASE")
    ap.add_argument("--base-env", action="append", default=[], metavar="NAME=VALUE",
                    help="an environment setting for BASE's runs (with --ab; repeatable)")
    ap.add_argument("--pairs", type=int, default=7, help="rounds with --ab (default 7)")
    ap.add_argument("--only", default="", help="cases whose 'label generations' has this")
    args = ap.parse_args()
    if args.ab is not None:
        ab(args.ab, args.base_env, args.pairs, args.only)
        return
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
