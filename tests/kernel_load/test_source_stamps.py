"""A kernel's cached machine code goes stale when a module its KernelSet names in
``sources`` changes, not only its own file (numba alone checks only its own file: after an
edit of only the callee's module, a warm cache ran the old callee)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

CALLEE = """
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__)

@kernels.kernel
def offset(x):
    return x + {value}
"""

CALLER = """
from camlab88.base.kernel_set import KernelSet
from stampcallee import offset

kernels = KernelSet(__name__, sources=("stampcallee",))

@kernels.export("int64(int64)")
def shifted(x):
    return offset(x) * 2
"""

RUN = """
import tests.support.print_compiles
from stampcaller import shifted
print("result", shifted(1))
"""


def _run(tmp_path: Path) -> list[str]:
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), CAMLAB88_AOT="0",
               PYTHONPATH=os.pathsep.join([str(tmp_path), str(ROOT)]))
    done = subprocess.run([sys.executable, "-c", RUN], env=env, capture_output=True,
                          text=True, timeout=300, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    return done.stdout.splitlines()


def test_an_edit_of_a_callee_module_recompiles_its_callers(tmp_path: Path) -> None:
    (tmp_path / "stampcaller.py").write_text(CALLER)
    callee = tmp_path / "stampcallee.py"
    callee.write_text(CALLEE.format(value=10))
    assert _run(tmp_path) == ["compiled stampcaller shifted", "compiled stampcallee offset",
                              "result 22"]
    assert _run(tmp_path) == ["result 22"]  # warm: both from the cache
    callee.write_text(CALLEE.format(value=20))  # only the callee's module changes
    assert _run(tmp_path) == ["compiled stampcaller shifted", "compiled stampcallee offset",
                              "result 42"]
    assert _run(tmp_path) == ["result 42"]


def test_the_stamps_are_active_with_the_numba_we_install() -> None:
    """A numba whose cache internals differ would leave numba's own stamps (returns False):
    this test says so rather than the stale-cache test passing by luck."""
    from camlab88.base.kernel_load import stamps_cover_sources

    assert stamps_cover_sources()
