"""Whole-process start-up of the ordinary commands, cold (first run after install) and warm.

    python benchmarks/bench_startup.py                 # every command, 5 warm runs each
    python benchmarks/bench_startup.py --runs 7 --cold-runs 2 --only snooker
    python benchmarks/bench_startup.py --demo          # also `camlab88 demo --headless`
    python benchmarks/bench_startup.py --ab ../main     # warm README commands, this tree vs another
    python benchmarks/bench_startup.py --readme [--demo]   # a newcomer's first-ever runs

Each command runs as its own process, as a user types it, in a scratch directory with the
shipped examples/. *Cold* gives every run an empty numba cache (NUMBA_CACHE_DIR), so every
kernel the command needs is compiled, as on the first run after install; *warm* runs share
one cache filled by an uncounted first run. Wall time per run (perf_counter around the
process) and its CPU time, min / median; the load average is printed before and after,
because on a shared 2-core machine the figures move with it (docs/perf/startup.md).
``--ab TREE`` runs every README command warm, alternately with this tree and with TREE (its
own ``.venv``), and a bare ``python -c "import numpy, numba"`` beside them, so all see the
same load: each tree's cache is filled first by its own ``camlab88 warm-up``; it prints each
command's medians and its margin over the bare import. ``--readme`` is a newcomer's first
hour: every command of README.md's "First ten minutes" (read from the README, as
tests/test_readme_walkthrough.py does) and the cellular automaton's example runs, in
order, in one scratch directory, all sharing one cache that starts empty (the first run
after install), each run once; it prints the "compiling" notices each command gave, so a
group compiled twice shows.
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BUDGET_S = 0.6  # every ordinary command, warm, whole process

COMMANDS: dict[str, list[str]] = {
    "snooker simulate --break": ["snooker", "simulate", "--break", "5", "--out", "break.cp"],
    "ca run (small)": ["ca", "run", "--rules", "life", "--pattern", "glider",
                       "--generations", "30"],
    "kas inbetween": ["kas", "inbetween", "sun_a", "sun_b", "--timing", "ease-in-out",
                      "--frames", "20", "--out", "sun.kas"],
    "rainbow render": ["rainbow", "render", "examples/rainbow/scene.json", "--out", "scene.png"],
    "sigma render (small stream)": ["sigma", "render", "--in", "examples/sigma/pgplot_goc.sig",
                                    "--out", "screen.png"],
    "camlab88 --help": ["--help"],
    "ca run --help": ["ca", "run", "--help"],
}
DEMO = {"demo --headless": ["demo", "--headless"]}
# README's cellular-automaton section, after the first ten minutes
README_MORE = [
    ["ca", "run", "--rules", "life", "--pattern", "gosper_gun", "--generations", "300",
     "--json"],
    ["ca", "run", "--rules", "maze", "--pattern", "maze_demo", "--generations", "98",
     "--png", "maze.png", "--zoom", "8"],
    ["ca", "run", "--rules", "turing_primes", "--pattern", "primes_25", "--generations",
     "300", "--json"],
    ["ca", "run", "--rules", "circuits", "--pattern", "adder_demo", "--generations", "300"],
]


# README sections after the CA's, whose commands run headless as printed
MORE_SECTIONS = ("Emulator controls", "Save states and seeking",
                 "The cellular automaton in 3-D: cells as actors")


def more_sections() -> list[list[str]]:
    """Their commands, less the ones that open a window (the editor without --headless)."""
    from tests.support.readme import section_commands

    return [argv[1:] for heading in MORE_SECTIONS for argv in section_commands(heading)
            if not (argv[1:3] == ["ca", "actors"] and "--headless" not in argv)]


def camlab88() -> list[str]:
    script = Path(sys.executable).with_name("camlab88")
    return [str(script)] if script.exists() else [sys.executable, "-m", "camlab88"]


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def run_once(argv: list[str], cwd: Path, cache: Path, script: list[str] | None = None,
             **extra: str) -> tuple[float, float]:
    """(wall, cpu) seconds of one process; CPU time (user + sys) moves less with the load."""
    took, cpu, _ = run_logged(argv, cwd, cache, script, **extra)
    return took, cpu


def run_logged(argv: list[str], cwd: Path, cache: Path, script: list[str] | None = None,
               **extra: str) -> tuple[float, float, str]:
    """run_once, and the process's stderr (``script``: the command, else this tree's)."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache), SDL_VIDEODRIVER="dummy", **extra)
    env.pop("DISPLAY", None)
    # as on a user's machine: Python keeps compiled modules (this sandbox sets
    # PYTHONDONTWRITEBYTECODE, which recompiles every module of ours in every process)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    done = subprocess.run((script or camlab88()) + argv, cwd=cwd, env=env, capture_output=True)
    took = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(script or camlab88())} {' '.join(argv)} failed:\n"
                         f"{done.stderr.decode()[-2000:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return took, cpu, done.stderr.decode(errors="replace")


def readme(work: Path, demo: bool) -> None:
    """A newcomer's first runs: README's commands in order, one cache, empty at the start."""
    sys.path.insert(0, str(ROOT))
    from tests.test_readme_walkthrough import walkthrough_commands, walkthrough_directories

    text = (ROOT / "README.md").read_text(encoding="utf-8")
    for d in walkthrough_directories(text):  # the README's `mkdir -p` lines
        (work / d).mkdir(parents=True, exist_ok=True)
    for line in text.splitlines():  # and the later sections' (the outputs' directories)
        if line.startswith("    mkdir -p "):
            for d in line.split()[2:]:
                (work / d).mkdir(parents=True, exist_ok=True)
    commands = [argv[1:] for argv in walkthrough_commands(text)] + README_MORE + more_sections()
    if demo:
        commands.append(["demo", "--headless"])
    cache = work / "newcomer-cache"
    extra = {"CAMLAB88_KAS_LIBRARY": str(work / "library"), "XDG_DATA_HOME": str(work / "data")}
    print("| command (first run after install, in README order) | wall s | CPU s "
          "| compiled | load before -> after |")
    print("|---|---|---|---|---|")
    for argv in commands:
        before = load()
        took, cpu, err = run_logged(argv, work, cache, **extra)
        notices = [line.split("compiling ")[1].split(" kernels")[0]
                   for line in err.splitlines() if line.startswith("camlab88: compiling ")]
        print(f"| `{' '.join(argv)}` | {took:.1f} | {cpu:.1f} | {', '.join(notices) or '-'} "
              f"| {before} -> {load()} |", flush=True)


def measure(argv: list[str], work: Path, runs: int,
            cold_runs: int) -> tuple[list[tuple[float, float]], ...]:
    cold = []
    for _ in range(cold_runs):
        with tempfile.TemporaryDirectory(dir=work) as fresh:
            cold.append(run_once(argv, work, Path(fresh)))
    warm_cache = work / "warm-cache"
    run_once(argv, work, warm_cache)  # fills the cache; not counted
    warm = [run_once(argv, work, warm_cache) for _ in range(runs)]
    return cold, warm


BARE = ["-c", "import numpy, numba"]


def ab(base: Path, work: Path, runs: int) -> None:
    """Warm README commands, this tree and ``base`` alternately, beside a bare numba import."""
    sys.path.insert(0, str(ROOT))
    from tests.test_readme_walkthrough import walkthrough_commands, walkthrough_directories

    text = (ROOT / "README.md").read_text(encoding="utf-8")
    for d in walkthrough_directories(text):
        (work / d).mkdir(parents=True, exist_ok=True)
    commands = [argv[1:] for argv in walkthrough_commands(text)] + README_MORE + more_sections()
    trees = {"new": camlab88(), "base": [str(base / ".venv" / "bin" / "camlab88")]}
    extra = {"CAMLAB88_KAS_LIBRARY": str(work / "library"), "XDG_DATA_HOME": str(work / "data")}
    for name, script in trees.items():  # each tree fills its own cache, uncounted
        run_logged(["warm-up"], work, work / f"cache-{name}", script=script, **extra)
        for argv in commands:  # and makes the files later commands read
            run_logged(argv, work, work / f"cache-{name}", script=script, **extra)
    print(f"load before: {load()}")
    print("| command | new wall s (min / median) | base wall s | new - bare import s "
          "| base - bare | load |")
    print("|---|---|---|---|---|---|")
    for argv in commands:
        before = load()
        times: dict[str, list[tuple[float, float]]] = {"new": [], "base": [], "bare": []}
        for _ in range(runs):
            for name, script in trees.items():
                times[name].append(run_once(argv, work, work / f"cache-{name}", script=script,
                                            **extra))
            times["bare"].append(run_once(BARE, work, work / "cache-new",
                                          script=[sys.executable]))
        med = {k: statistics.median(w for w, _ in v) for k, v in times.items()}
        print(f"| `{' '.join(argv)}` | {fmt(times['new'], 0)} | {fmt(times['base'], 0)} "
              f"| {med['new'] - med['bare']:+.2f} | {med['base'] - med['bare']:+.2f} "
              f"| {before} -> {load()} |", flush=True)


def fmt(runs: list[tuple[float, float]], which: int) -> str:
    xs = [r[which] for r in runs]
    return f"{min(xs):.2f} / {statistics.median(xs):.2f}" if xs else "-"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=5, help="warm runs per command (default 5)")
    ap.add_argument("--cold-runs", type=int, default=2, help="cold runs per command (default 2)")
    ap.add_argument("--only", help="only commands whose name contains this")
    ap.add_argument("--demo", action="store_true", help="also time `demo --headless`")
    ap.add_argument("--readme", action="store_true",
                    help="README's commands in order, first runs from an empty cache")
    ap.add_argument("--ab", type=Path, metavar="TREE",
                    help="warm README commands: this tree against TREE (with its .venv)")
    args = ap.parse_args(argv)
    commands = {**COMMANDS, **(DEMO if args.demo else {})}
    if args.only:
        commands = {k: v for k, v in commands.items() if args.only in k}
    print(f"# bench_startup: {platform.machine()} {platform.python_version()}, "
          f"{os.cpu_count()} CPUs, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    with tempfile.TemporaryDirectory(prefix="camlab88-startup-") as tmp:
        work = Path(tmp)
        shutil.copytree(ROOT / "examples", work / "examples")
        if args.ab:
            ab(args.ab.resolve(), work, args.runs)
            return 0
        if args.readme:
            readme(work, args.demo)
            return 0
        print("| command | cold wall s | cold CPU s | warm wall s | warm CPU s "
              "| load before -> after |")
        print("|---|---|---|---|---|---|")
        for name, cmd in commands.items():
            before = load()
            cold, warm = measure(cmd, work, args.runs, args.cold_runs)
            over = statistics.median(w for w, _ in warm) > BUDGET_S and "demo" not in name
            print(f"| `{name}` | {fmt(cold, 0)} | {fmt(cold, 1)} "
                  f"| {fmt(warm, 0)}{' (over)' if over else ''} | {fmt(warm, 1)} "
                  f"| {before} -> {load()} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
