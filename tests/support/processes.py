"""Python code run in a fresh interpreter: what a first import or a new process sees; a
child process that a failing test does not leave running."""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def fresh_python(code: str, *args: str, cwd: Path | None = None) -> str:
    """Run ``python -c code args`` with this tree first on the path; its standard output. A
    non-zero exit fails the test with the child's standard error."""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    result = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True,
                            timeout=120, env=env, cwd=cwd, check=False)
    assert result.returncode == 0, result.stderr
    return result.stdout


@contextmanager
def child(argv: list[str], **popen: object) -> Iterator[subprocess.Popen]:
    """``subprocess.Popen(argv)`` with its output read as text through pipes; killed (and
    waited for) if it is still running when the block ends, as when an assertion fails."""
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            **popen)
    try:
        yield proc
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
