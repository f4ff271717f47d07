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


# The child is started by a small launcher, which reports the child's rusage: on Linux a
# process's peak RSS (ru_maxrss) starts from its parent's RSS at the fork (exec keeps the
# forked copy's high-water mark), so a child forked straight from a pytest worker that has
# grown to 480 MB reports at least 480 MB whatever it did. The launcher is a fresh, small
# interpreter; its child's figure is the child's own.
_LAUNCHER = """
import json, os, subprocess, sys
child = subprocess.Popen(sys.argv[2:])
_, status, usage = os.wait4(child.pid, 0)
child.returncode = os.waitstatus_to_exitcode(status)
with open(sys.argv[1], "w") as fh:
    json.dump({"status": child.returncode, "maxrss_kb": usage.ru_maxrss,
               "cpu": usage.ru_utime + usage.ru_stime}, fh)
"""


def camlab88(cwd: Path, *words: str, budget: str | None = None, timeout: float = 300) -> Run:
    """``python -m camlab88 words...`` in ``cwd`` with ``CAMLAB88_BUDGET=budget`` (None:
    the default), measured. A child still running after ``timeout`` is killed and fails."""
    import json
    import signal

    env = {**os.environ, "PYTHONPATH": str(ROOT), "SDL_VIDEODRIVER": "dummy"}
    env.pop("CAMLAB88_BUDGET", None)
    if budget is not None:
        env["CAMLAB88_BUDGET"] = budget
    report = cwd / "_rusage.json"
    with open(cwd / "_stdout.txt", "w+") as out, open(cwd / "_stderr.txt", "w+") as err:
        start = time.monotonic()
        launcher = subprocess.Popen(
            [sys.executable, "-c", _LAUNCHER, str(report), sys.executable, "-m", "camlab88",
             *words], env=env, cwd=cwd, stdout=out, stderr=err, start_new_session=True)
        try:
            launcher.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(launcher.pid, signal.SIGKILL)  # the launcher's session: it and the child
            launcher.wait()
            raise AssertionError(f"camlab88 {' '.join(words)} ran past {timeout} s") from None
        seconds = time.monotonic() - start
        got = json.loads(report.read_text())
        report.unlink()
        out.seek(0)
        err.seek(0)
        return Run(got["status"], err.read(), out.read(), seconds, got["maxrss_kb"] / 1024,
                   got["cpu"])
