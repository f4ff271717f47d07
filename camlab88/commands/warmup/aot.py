"""The kernel modules compiled ahead of time by ``camlab88 warm-up`` (base/aot_build.py), in
one place: a module listed here must declare its kernels through base.kernel_set.KernelSet,
and tests/aot builds every one and compares its results with the JIT path's."""

from __future__ import annotations

import sys
import time

# what a `ca run` loads: the direct engine, the pattern readers' scanner, HashLife
AOT_MODULES: tuple[str, ...] = (
    "camlab88.apps.ca.grid_stats",
    "camlab88.apps.ca.rle_scan",
    "camlab88.apps.ca.kernels",
    "camlab88.apps.ca.hashlife.store",
    "camlab88.apps.ca.hashlife.leaf",
    "camlab88.apps.ca.hashlife.census",
    "camlab88.apps.ca.hashlife.grid",
    "camlab88.apps.ca.hashlife.upkeep",
    "camlab88.apps.ca.hashlife.cells",
    "camlab88.apps.ca.hashlife.listing",
    "camlab88.apps.ca.hashlife.cellgrid",
    "camlab88.apps.ca.hashlife.bits.leaves",
    "camlab88.apps.ca.hashlife.bits.window",
    "camlab88.apps.ca.hashlife.evolve",
)

STEP = "ahead-of-time modules"


def build_step(index: int, total: int) -> None:
    """Build the listed modules' extensions, one line each; a failure (no C compiler, say)
    is reported and leaves those modules on the JIT path."""
    from camlab88.base import aot_build, aot_load

    print(f"[{index}/{total}] {STEP} ...", end="", file=sys.stderr, flush=True)
    if not aot_load.enabled():
        print(f" skipped ({aot_load.OFF_VARIABLE} is off)", file=sys.stderr, flush=True)
        return
    t0 = time.perf_counter()
    outcomes = aot_build.build(AOT_MODULES)
    print(f" ({time.perf_counter() - t0:.1f} s, in {aot_load.directory()})", file=sys.stderr)
    for module, outcome in outcomes.items():
        note = ("; its kernels stay JIT-compiled" if outcome.startswith("failed") else "")
        print(f"      {module}: {outcome}{note}", file=sys.stderr, flush=True)
