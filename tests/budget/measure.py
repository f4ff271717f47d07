"""A command run in a child process, measured: its exit status, standard error, wall time
and peak resident memory (``os.wait4``'s rusage of that child alone)."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


@dataclass
class Run:
    status: int
    stderr: str
    stdout: str
    seconds: float  # wall time
    peak_mb: float
    cpu: float  # user + system seconds of the child: what it cost, whatever the load


def camlab88(cwd: Path, *words: str, budget: str | None = None, timeout: float = 300) -> Run:
    """``python -m camlab88 words...`` in ``cwd`` with ``CAMLAB88_BUDGET=budget`` (None:
    the default), measured. A child still running after ``timeout`` is killed and fails."""
    env = {**os.environ, "PYTHONPATH": str(ROOT), "SDL_VIDEODRIVER": "dummy"}
    env.pop("CAMLAB88_BUDGET", None)
    if budget is not None:
        env["CAMLAB88_BUDGET"] = budget
    with open(cwd / "_stdout.txt", "w+") as out, open(cwd / "_stderr.txt", "w+") as err:
        start = time.monotonic()
        child = subprocess.Popen([sys.executable, "-m", "camlab88", *words], env=env,
                                 cwd=cwd, stdout=out, stderr=err)
        deadline = start + timeout
        while True:  # wait4: this child's own rusage, not the test process's other children
            pid, wstatus, usage = os.wait4(child.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() > deadline:
                child.kill()
                os.wait4(child.pid, 0)
                raise AssertionError(f"camlab88 {' '.join(words)} ran past {timeout} s")
            time.sleep(0.02)
        seconds = time.monotonic() - start
        child.returncode = os.waitstatus_to_exitcode(wstatus)  # Popen must not wait again
        out.seek(0)
        err.seek(0)
        return Run(child.returncode, err.read(), out.read(), seconds, usage.ru_maxrss / 1024,
                   usage.ru_utime + usage.ru_stime)
