"""camlab88.base.kernel_notice never imports numba itself: a group registered before numba is
imported is still announced on a cold compile, and a process that never imports numba
(its kernels ahead of time) stays without it."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from camlab88.base import kernel_notice

ROOT = Path(__file__).resolve().parents[2]

EARLY = """
from camlab88.base.kernel_notice import announce_compiles

announce_compiles("early toy", 2.0, __name__)  # before numba, as a package __init__ may

import importlib.util

importlib.util.find_spec("numba")  # only looked up (not imported) first: still announced

from numba import njit


@njit(cache=True)
def thrice(x):
    return 3 * x
"""


def _run(tmp_path: Path, code: str) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"),
               PYTHONPATH=os.pathsep.join([str(tmp_path), str(ROOT)]))
    return subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                          text=True, timeout=300, cwd=tmp_path)


def test_registered_before_numba_is_still_announced(tmp_path: Path) -> None:
    (tmp_path / "earlytoy.py").write_text(EARLY)
    code = ("import earlytoy\nfrom camlab88.base import kernel_load\n"
            "print(earlytoy.thrice(14), kernel_load.active())\n")
    cold = _run(tmp_path, code)
    assert cold.returncode == 0, cold.stderr
    assert cold.stdout.split() == ["42", "True"]
    assert cold.stderr == kernel_notice.notice_line("early toy", 2.0) + "\n"
    warm = _run(tmp_path, code)
    assert warm.stdout.split() == ["42", "True"] and warm.stderr == ""


def test_registering_alone_imports_no_numba(tmp_path: Path) -> None:
    code = ("import sys\nfrom camlab88.base.kernel_notice import announce_compiles\n"
            "announce_compiles('toy', 1.0, 'nowhere')\nprint('numba' in sys.modules)\n")
    done = _run(tmp_path, code)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "False\n"
