"""bgolly, Golly's command-line program, as an oracle: where it is, and a pattern run by it.

Found by $CAMLAB88_BGOLLY, then /opt/golly/usr/bin/bgolly (where .ci/run unpacks the Debian
package golly), then ``bgolly`` on PATH. Tests that need it skip with a message saying so.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from camlab88.apps.ca.patterns import read_pattern

DATA = Path(__file__).resolve().parents[1] / "data" / "ca" / "golly"
FIXED = Path("/opt/golly/usr/bin/bgolly")


def bgolly() -> str | None:
    env = os.environ.get("CAMLAB88_BGOLLY")
    if env:
        return env
    if FIXED.is_file() and os.access(FIXED, os.X_OK):
        return str(FIXED)
    return shutil.which("bgolly")


def need_bgolly() -> str:
    found = bgolly()
    if found is None:
        pytest.skip("bgolly not found (set CAMLAB88_BGOLLY, unpack the Debian package golly "
                    "into /opt/golly as .ci/run does, or put bgolly on PATH)")
    return found


def golly_cells(path: Path, generations: int, out: Path, rule_table: bool
                ) -> set[tuple[int, int, int]]:
    """The cells (x, y, state) relative to Golly's origin after ``generations``, as bgolly
    writes them in macrocell (our reader reads that; the reader is checked on its own)."""
    algo = ["-a", "RuleLoader", "-s", f"{DATA}/"] if rule_table else ["-h"]
    run = subprocess.run([need_bgolly(), "-m", str(generations), "-i",
                          str(max(generations, 1)), *algo, "-o", str(out), str(path)],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0 and out.exists(), run.stdout + run.stderr
    p = read_pattern(out)
    return {(int(x) - p.ref[0], int(y) - p.ref[1], int(t)) for x, y, t in zip(p.xs, p.ys, p.ts)}
