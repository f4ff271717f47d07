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
from camlab88.base.kernel_set import KernelSet
kernels = KernelSet(__name__)


@kernels.kernel
def twice(x):
    return 2 * x
"""

OUTER = """
from camlab88.base.kernel_set import KernelSet
from {package}.inner import twice
kernels = KernelSet(__name__{sources})


@kernels.export("int64(int64)")
def quadruple(x):
    return twice(twice(x))
"""

REFUSED = """
from pathlib import Path
from camlab88.base import aot_build
print(sorted(aot_build.kernel_dependencies("{package}.outer")))
print(aot_build.build_here("{package}.outer", Path("never")).split(":")[0])
"""

COVERED = """
from pathlib import Path
from camlab88.base import aot_build, aot_load
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


def test_a_module_of_kernels_only_gets_a_marker(tmp_path: Path) -> None:
    """No exports, so nothing to compile on its own (its kernels are compiled into the
    callers' extensions): the build leaves a marker, and the module then loads without
    numba; edited, it takes the JIT path."""
    (tmp_path / "onlykernels.py").write_text(INNER)
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"),
               CAMLAB88_AOT_DIR=str(tmp_path / "aot"),
               PYTHONPATH=os.pathsep.join([str(tmp_path), str(ROOT)]))
    build = subprocess.run([sys.executable, "-m", "camlab88.base.aot_build", "--out",
                            str(tmp_path / "aot"), "onlykernels"], capture_output=True,
                           text=True, timeout=300, cwd=tmp_path, env=dict(env, CAMLAB88_AOT="0"))
    assert build.stdout == "onlykernels\tbuilt\n", build.stderr
    assert [p.suffix for p in (tmp_path / "aot").iterdir()] == [".kernels-only"]
    code = ("import sys, onlykernels as k\n"
            "print(k.kernels.mode, k.twice(4), 'numba' in sys.modules)\n")

    def run() -> str:
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                              timeout=300, cwd=tmp_path, env=env)
        assert done.returncode == 0, done.stderr
        return done.stdout

    assert run() == "aot 8 False\n"
    (tmp_path / "onlykernels.py").write_text(INNER + "# edited\n")
    assert run() == "jit 8 True\n"


def test_without_a_c_compiler_the_warm_up_step_says_so(tmp_path: Path) -> None:
    env = dict(os.environ, CC="/bin/false", NUMBA_CACHE_DIR=str(tmp_path / "cache"),
               CAMLAB88_AOT_DIR=str(tmp_path / "aot"), PYTHONPATH=str(ROOT))
    code = "from camlab88.commands.warmup.aot import build_step\nbuild_step(9, 9)\n"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=600, cwd=tmp_path, env=env)
    assert done.returncode == 0, done.stderr
    lines = done.stderr.splitlines()
    assert lines[0].startswith("[9/9] ahead-of-time modules ...")
    assert "camlab88.apps.ca.kernels: failed: no working C compiler" in done.stderr
    assert all(ln.endswith("its kernels stay JIT-compiled") for ln in lines[1:] if "failed" in ln)
    assert not (tmp_path / "aot").exists() or not any((tmp_path / "aot").glob("*.so"))
