"""Snooker benchmark: a 22-ball break simulated to rest (target <= 50 ms).

    python benchmarks/bench_snooker.py

Prints, for several break speeds, the median wall time of the physics alone
(`physics.simulate_to_rest`) and of the whole timeline (physics + rules + both frame
stacks), with the event scan and event-free frame loop compiled by numba and, for comparison, the
same algorithm in plain Python (`use_numba=False`).
The numba compile time (first call) is reported separately and excluded from the medians.
"""

from __future__ import annotations

import platform
import statistics
import time

import camlab88.apps.snooker.physics as physics
from camlab88.apps.snooker.layout import break_off
from camlab88.apps.snooker.table import Table
from camlab88.apps.snooker.timeline import Timeline

REPEATS = 15


def _median_ms(fn) -> float:
    times = []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        fn()
        times.append((time.perf_counter() - t0) * 1000.0)
    return statistics.median(times)


def main() -> None:
    table = Table()
    print(f"python {platform.python_version()}")
    t0 = time.perf_counter()
    physics.simulate_to_rest(table, break_off(table, 5.0))
    print(f"first call (includes numba compile): {(time.perf_counter() - t0) * 1000:.0f} ms")
    print(f"{'break m/s':>9} {'frames':>6} {'events':>6} {'physics ms':>10} {'timeline ms':>11} "
          f"{'pure-python ms':>14}")
    for speed in (3.0, 5.0, 8.0, 12.0):
        start = break_off(table, speed)
        frames, events = physics.simulate_to_rest(table, start)

        def phys(start=start) -> None:
            physics.simulate_to_rest(table, start)

        def whole(start=start) -> None:
            Timeline(table, start).simulate_to_rest()

        def python(start=start) -> None:
            physics.simulate_to_rest(table, start, use_numba=False)

        jit_ms = _median_ms(phys)
        tl_ms = _median_ms(whole)
        py_ms = _median_ms(python)
        print(f"{speed:9.1f} {len(frames):6d} {len(events):6d} {jit_ms:10.1f} {tl_ms:11.1f} "
              f"{py_ms:14.1f}")


if __name__ == "__main__":
    main()
