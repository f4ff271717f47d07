"""A kernel module whose kernels call another kernel module's must declare it as a source
(its code is compiled into the extension, so its edits must change the key); the build
refuses one that does not."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

INNER = """
from base.kernel_set import KernelSet
kernels = KernelSet(__name__)


@kernels.kernel
def twice(x):
    return 2 * x
"""

OUTER = """
from base.kernel_set import KernelSet
from {package}.inner import twice
kernels = KernelSet(__name__{sources})


@kernels.export("int64(int64)")
def quadruple(x):
    return twice(twice(x))
"""

REFUSED = """
from pathlib import Path
from base import aot_build
print(sorted(aot_build.kernel_dependencies("{package}.outer")))
print(aot_build.build_here("{package}.outer", Path("never")).split(":")[0])
"""

COVERED = """
from pathlib import Path
from base import aot_build, aot_load
import {package}.outer as outer
print(sorted(aot_build.kernel_dependencies("{package}.outer")))
before = aot_load.key(outer.__name__, outer.kernels.sources)
inner = Path("{package}/inner.py")
inner.write_text(inner.read_text() + "# edited")
print(before != aot_load.key(outer.__name__, outer.kernels.sources))
"""


def _check(tmp_path: Path, package: str, sources: str, code: str) -> list[str]:
    (tmp_path / package).mkdir()
    (tmp_path / package / "__init__.py").write_text("")
    (tmp_path / package / "inner.py").write_text(INNER)
    (tmp_path / package / "outer.py").write_text(OUTER.format(package=package,
                                                              sources=sources))
    env = dict(os.environ, CAMLAB88_AOT="0", NUMBA_CACHE_DIR=str(tmp_path / "cache"),
               CAMLAB88_AOT_DIR=str(tmp_path / "aot"),
               PYTHONPATH=os.pathsep.join([str(tmp_path), str(ROOT)]))
    done = subprocess.run([sys.executable, "-c", code.format(package=package)], env=env,
                          capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    return done.stdout.splitlines()


def test_an_undeclared_kernel_module_is_refused(tmp_path: Path) -> None:
    assert _check(tmp_path, "undeclared", "", REFUSED) == ["['undeclared.inner']", "failed"]


def test_a_declared_one_is_in_the_key(tmp_path: Path) -> None:
    assert _check(tmp_path, "declared", ', sources=("declared.inner",)', COVERED) == [
        "['declared.inner']", "True"]
