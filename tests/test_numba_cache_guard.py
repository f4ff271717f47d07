"""The session's numba-cache guard (tests/conftest.py) sees a kernel cached with two
signatures, and our kernels are called with one each."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

from tests.support.numba_cache import overloaded_kernels

ROOT = Path(__file__).resolve().parents[1]

TOY = textwrap.dedent("""
    from numba import njit

    @njit(cache=True)
    def twice(x):
        return x + x

    @njit(cache=True)
    def once(x):
        return x * 3
""")


def _run(tmp_path: Path, code: str) -> None:
    path = os.pathsep.join([str(tmp_path), str(ROOT)])
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=path)
    subprocess.run([sys.executable, "-c", code], env=env, check=True, cwd=tmp_path)


def test_two_signatures_of_one_kernel_are_found(tmp_path: Path) -> None:
    (tmp_path / "toy.py").write_text(TOY)
    _run(tmp_path, "import toy; toy.twice(1); toy.twice(1.5); toy.once(2); toy.once(4)")
    bad = overloaded_kernels(tmp_path / "cache")
    assert list(bad) == [next(k for k in bad if "twice" in k)]
    assert sorted(bad.popitem()[1]) == ["(float64,)", "(int64,)"]


def test_rainbow_compile_keeps_one_signature(tmp_path: Path) -> None:
    """compile_rows types its call of _sort_unique with a literal 0 first; the explicit
    signature keeps that from becoming a second cached signature."""
    _run(tmp_path, textwrap.dedent("""
        from camlab88.emulator.rainbow import Rainbow
        r = Rainbow()
        r.set_lut(0, [(0, 0, 0), (255, 0, 0)])
        p = r.create_pad(50, 50, 1)
        r.canvas(p).rect(0, 0, 50, 50, 1)
        r.map(0, p, 10, 10)
        assert tuple(r.frame()[20, 20]) == (255, 0, 0)
    """))
    assert overloaded_kernels(tmp_path / "cache") == {}
