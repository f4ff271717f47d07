"""What the benchmark scripts share: this checkout first on the import path (so a script run
as ``python benchmarks/bench_x.py`` measures the tree it sits in, tests' helpers included),
the load average to print beside each figure, and the timing loops."""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))


def load() -> str:
    """The 1, 5 and 15 minute load averages: the machine may be shared."""
    a, b, c = os.getloadavg()
    return f"load {a:.2f} {b:.2f} {c:.2f}"


def times(fn: Callable[[], object], repeat: int) -> list[float]:
    """Wall seconds of ``repeat`` calls of ``fn``, one a call."""
    out = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t)
    return out


def rate(step: Callable[[], object], n: int) -> float:
    """Calls per second of ``step`` over ``n`` calls in a row."""
    t = time.perf_counter()
    for _ in range(n):
        step()
    return n / (time.perf_counter() - t)
