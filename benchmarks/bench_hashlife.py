"""Benchmark of the CA engine's HashLife beside lifelib's (run by hand:
python benchmarks/bench_hashlife.py [--no-process]).

Life written in the rule language (thesis figure 7.6) jumped by apps/ca/hashlife, and the
same patterns run by lifelib (Adam P. Goucher's C++ HashLife, "python-lifelib" on PyPI),
in the same run on the same machine:

* acorn to generation 5206, the Gosper gun to 100,000, the puffer train to 30,000;
* a long jump that fills much of the plane: the spacefiller to 65,000 generations, when it
  covers about 65000 x 65000 of the 65536-square plane (population known in closed form:
  [(t+17)^2+511]/4 for t divisible by 4).

Each figure is the minimum and median of several runs, each with an empty node table (a
fresh lifelib lifetree), as CPU time (this process's) and wall time of the jump and the
population after it.  On both sides the table is made and the pattern loaded into it as a
tree before the clock starts (lifelib's ``lt.pattern(rle)`` builds its tree; ours is built
the same way the first jump would, then adopted by the engine); the machine may be
shared with other work, so the load average is printed beside each.  "ratio" is ours /
lifelib on minimum CPU time (goal: at most 1).  "path" says which of our HashLife paths
ran (binary: two-state rules on a plane of 1s, 16 x 16-cell bit leaves; generic: leaves of
life-form values), then its table: bytes allocated, nodes and leaves made.  Then the whole
process of ``camlab88 ca run --engine hashlife`` for the three patterns, start-up
included (goal: under 3 s together).

lifelib is for this benchmark only, not a dependency of camlab88:
``.venv/bin/pip install python-lifelib`` (its first use compiles C++ with g++, about a minute).
"""

from __future__ import annotations

import os

# As `camlab88` itself sets it (camlab88/cli.py): numpy's BLAS threads, spinning after a
# call, would otherwise be counted in this process's CPU time.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

from camlab88.apps.ca.engine import CENTRE, Engine
from camlab88.apps.ca.hashlife import tree as trees
from camlab88.apps.ca.hashlife.algorithm import HashLife
from camlab88.apps.ca.hashlife.generic import GenericRun
from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules

HERE = Path(__file__).parent
CASES = [("acorn", pattern_path("acorn"), 5206),
         ("gosper_gun", pattern_path("gosper_gun"), 100_000),
         ("puffer_train", str(HERE / "patterns" / "puffer_train.rle"), 30_000),
         ("spacefiller", str(HERE / "patterns" / "spacefiller.rle"), 65_000)]
# The generic path (multi-state rules, leaves of life-form values): ours only.
GENERIC = [("turing_primes", "turing_primes", pattern_path("primes_25"), 4096),
           ("circuits", "circuits", pattern_path("adder_demo"), 2048)]
RUNS = 25  # both sides; a sub-millisecond jump needs more than 5 runs for a steady minimum


def load() -> str:
    return f"load {os.getloadavg()[0]:.2f}"


def rle_body(path: str) -> str:
    lines = [ln for ln in Path(path).read_text().splitlines()
             if ln and not ln.startswith(("#", "x"))]
    return "".join(lines)


def ours(path: str, generations: int,
         rules_name: str = "life") -> tuple[list[float], list[float], int, str]:
    rules = load_rules(rules_path(rules_name))
    xs, ys, ts = read_pattern(path).placed(CENTRE, CENTRE, "identity")
    cpu, wall = [], []
    for _ in range(RUNS):
        for key in ("hashlife_run", "hashlife_bits_run"):  # an empty node table each run
            rules._tables.pop(key, None)
        e = Engine(rules, algorithm="hashlife")
        e.set_cells(xs, ys, ts)
        run = HashLife.binary(e) or GenericRun.of(rules, e.hashlife_memory)
        e.adopt(trees.adopt(run, trees.plane(run, e)))  # the table and the tree, as lifelib's
        c, w = time.process_time(), time.perf_counter()
        e.step(generations)
        pop = e.population
        cpu.append(time.process_time() - c)
        wall.append(time.perf_counter() - w)
    box = e.stats()["bbox"]  # once, after the runs (lifelib's runs follow one another too)
    bits = rules._tables.get("hashlife_bits_run")
    if bits is not None:
        s = bits.store
        table = f"binary {s.bytes / 2**20:.1f} MB, {s.count:,} nodes + {s.leaf_count:,} leaves"
    else:
        s = rules._tables["hashlife_run"].store
        # nodes made: ids start after the leaves' (before one store: after 65537 value ids)
        made = s.count - (1 if hasattr(s, "leaf_count") else 65537)
        table = f"generic {s.bytes / 2**20:.1f} MB, {made:,} nodes"
    return cpu, wall, pop, f"{table}, box {box}"


def theirs(path: str, generations: int) -> tuple[list[float], list[float], int] | str:
    try:
        import lifelib
    except ImportError:
        return "lifelib not installed (.venv/bin/pip install python-lifelib)"
    sess = lifelib.load_rules("b3s23")
    body = rle_body(path)
    cpu, wall = [], []
    for _ in range(RUNS):
        lt = sess.lifetree(memory=1000)
        p = lt.pattern(body)
        c, w = time.process_time(), time.perf_counter()
        pop = p[generations].population
        cpu.append(time.process_time() - c)
        wall.append(time.perf_counter() - w)
    return cpu, wall, pop


def fmt(xs: list[float]) -> str:
    digits = 2 if min(xs) < 0.01 else 1  # sub-10 ms jumps: tenths of a millisecond are 20 %
    return f"{min(xs) * 1e3:8.{digits}f} / {statistics.median(xs) * 1e3:8.{digits}f} ms"


def children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def whole_processes() -> None:
    """Three ``ca run`` processes, one after another, as a user would type them; and the
    same three with no generations (start-up, reading, statistics: the floor)."""
    exe = str(Path(sys.executable).with_name("camlab88"))
    for label, engine, zero in (("jumps", "hashlife", False), ("start-up only", "direct", True)):
        for _ in range(3):
            start, cpu = time.perf_counter(), children_cpu()
            for _name, path, gens in CASES[:3]:
                subprocess.run([exe, "ca", "run", "--rules", "life", "--pattern", path,
                                "--generations", "0" if zero else str(gens), "--engine",
                                engine], check=True, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
            print(f"  three ca run processes ({label}): {time.perf_counter() - start:.2f} s "
                  f"wall, {children_cpu() - cpu:.2f} s CPU   {load()}")


def machine() -> str:
    cpu = "?"
    info = Path("/proc/cpuinfo")
    if info.exists():
        names = [ln.split(":", 1)[1].strip() for ln in info.read_text().splitlines()
                 if ln.startswith("model name")]
        cpu = names[0] if names else cpu
    return (f"{time.strftime('%Y-%m-%d %H:%M')}, {cpu}, {os.cpu_count()} cores, python "
            f"{sys.version.split()[0]}, {load()}")


def main() -> None:
    print(machine())
    print("pattern        generations   population   ours cpu min / median    "
          "lifelib cpu min / median   ratio   ours wall min / median   path and table")
    for name, path, gens in CASES:
        cpu, wall, pop, table = ours(path, gens)
        ref = theirs(path, gens)
        if isinstance(ref, str):
            print(f"{name:14} {gens:>11,} {pop:>12,}  {fmt(cpu)}   {ref}\n{'':16}{table}")
            continue
        rcpu, _, rpop = ref
        same = "" if rpop == pop else f"  POPULATIONS DIFFER: lifelib {rpop}"
        ratio = min(cpu) / max(min(rcpu), 1e-4)
        print(f"{name:14} {gens:>11,} {pop:>12,}  {fmt(cpu)}   {fmt(rcpu)}   {ratio:5.2f}x  "
              f"{fmt(wall)}  {table}   {load()}{same}")
    for name, rules_name, path, gens in GENERIC:
        cpu, wall, pop, table = ours(path, gens, rules_name)
        print(f"{name:14} {gens:>11,} {pop:>12,}  {fmt(cpu)}   {'':26}{'':9}{fmt(wall)}  "
              f"{table}   {load()}")
    if "--no-process" not in sys.argv:
        whole_processes()


if __name__ == "__main__":
    main()
