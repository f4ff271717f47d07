"""--speed: how closely a paced replay of a KAS viewer recording follows the period's time.

Run by hand: ``python benchmarks/bench_controls.py [RUNS]``. Makes the demo walk
(``kas inbetween walk_a walk_b ...``), records ``kas view walk.kas --every`` (every frame
over the 9600-baud line, 3.57 s of line time) and replays it headless at ``--speed 1``,
``--speed 10`` and flat out. The figure is the paced span: the wall time from the first to
the last frame-limiter call against the virtual time between them (the process start and
the replay's set-up are outside it, and are printed separately). docs/perf/controls.md
holds a copy with the machine's load.
"""

from __future__ import annotations

import contextlib
import io
import os
import sys
import tempfile
import time
from pathlib import Path


def _load() -> str:
    try:
        return " / ".join(f"{v:.2f}" for v in os.getloadavg())
    except OSError:
        return "unknown"


def _record(tmp: Path) -> Path:
    from camlab88.cli import main

    os.chdir(tmp)
    quiet = io.StringIO()
    with contextlib.redirect_stdout(quiet), contextlib.redirect_stderr(quiet):
        assert main(["kas", "inbetween", "walk_a", "walk_b", "--path", "walk_path",
                     "--timing", "walk_ticks", "--out", "walk.kas"]) == 0
        assert main(["kas", "view", "walk.kas", "--every", "--headless",
                     "--record", "view.session"]) == 0
    return tmp / "view.session"


def _paced(session: Path, speed: str | None) -> tuple[float, float, float]:
    """(virtual span, wall span, whole command wall) of one headless replay."""
    from camlab88.cli import main
    from camlab88.emulator.harness import pace

    calls: list[tuple[float, float]] = []
    original = pace.Pacer.pace

    def logged(self, t):
        original(self, t)
        calls.append((float(t), time.monotonic()))

    argv = ["replay", str(session), "--headless", "--check"]
    if speed is not None:
        argv += ["--speed", speed]
    pace.Pacer.pace = logged
    t0 = time.monotonic()
    try:
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            assert main(argv) == 0
    finally:
        pace.Pacer.pace = original
    whole = time.monotonic() - t0
    (v0, w0), (v1, w1) = calls[0], calls[-1]
    return v1 - v0, w1 - w0, whole


def main(runs: int = 3) -> None:
    print(f"machine: {os.cpu_count()} cores, load average before: {_load()}")
    with tempfile.TemporaryDirectory(prefix="bench-controls-") as tmp:
        session = _record(Path(tmp))
        _paced(session, None)  # warm: kernels loaded, caches filled
        for speed in ("1", "10", None):
            for _ in range(runs):
                virtual, wall, whole = _paced(session, speed)
                want = virtual / float(speed) if speed else None
                off = f"{100 * (wall - want) / want:+.2f} %" if want else "-"
                print(f"--speed {speed or 'flat out':>8}: virtual {virtual:.3f} s, paced wall "
                      f"{wall:.3f} s (target {want or 0:.3f} s, {off}); whole replay "
                      f"{whole:.2f} s; load {_load()}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 3)
