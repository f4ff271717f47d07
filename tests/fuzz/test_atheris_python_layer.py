"""Under atheris only the Python layer is instrumented: a numba kernel first compiled after
``instrument_python_layer()`` (here the Sigma boundary fill, from a fresh numba cache)
compiles from its own bytecode, not atheris's, so a fill order is not a false crash."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

CODE = textwrap.dedent("""
    from fuzz.targets import TARGETS
    from fuzz import atheris_target

    target = TARGETS["sigma-stream"]
    target.check(target.seeds()[0])  # imports the terminal; the fill kernel not yet compiled
    kept = atheris_target.instrument_python_layer()  # (atheris.instrument_all(): it fails)
    assert kept > 0, kept
    from camlab88.protocols.sigma import Encoder
    e = Encoder()
    target.check(e.flag() + e.move(100, 100) + e.fill(1))  # compiles _boundary_fill now
    print("ok")
""")


def _run(tmp_path: Path) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PYTHONPATH=str(ROOT), NUMBA_CACHE_DIR=str(tmp_path / "cache"))
    return subprocess.run([sys.executable, "-c", CODE], env=env, cwd=ROOT,
                          capture_output=True, text=True, timeout=600)


def test_kernels_compile_uninstrumented_under_atheris(tmp_path: Path) -> None:
    pytest.importorskip("atheris", reason="atheris is not installed (pip install -e '.[fuzz]')")
    done = _run(tmp_path)
    assert done.returncode == 0 and done.stdout.strip().endswith("ok"), done.stderr[-2000:]
