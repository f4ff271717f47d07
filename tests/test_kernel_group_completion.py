"""A kernel group compiles whole on its first cold use: the program that first needs one of
its kernels also compiles the others (as it ends), so a later program needing another kernel
of the group loads it from the cache, with no second "compiling" notice."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

GROUP = """
from numba import njit
from camlab88.base.kernel_notice import announce_compiles

announce_compiles("toy", 1.0, __name__, completion="toygroup:complete")

@njit(cache=True)
def double(x):
    return 2 * x

@njit(cache=True)
def triple(x):
    return 3 * x

def complete():
    double(1)
    triple(1)
"""


PRINT_COMPILES = "import tests.support.print_compiles\n"


def _run(tmp_path: Path, code: str) -> subprocess.CompletedProcess[str]:
    (tmp_path / "toygroup.py").write_text(GROUP)
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"),
               PYTHONPATH=os.pathsep.join([str(tmp_path), str(ROOT)]))
    code = PRINT_COMPILES + textwrap.dedent(code)
    return subprocess.run([sys.executable, "-c", code],
                          env=env, capture_output=True, text=True, timeout=120)


def test_the_first_program_compiles_the_whole_group_and_the_next_compiles_nothing(
        tmp_path: Path) -> None:
    first = _run(tmp_path, "import toygroup\nprint(toygroup.double(21))\n")
    assert first.returncode == 0, first.stderr
    assert first.stdout.splitlines() == ["compiled toygroup double", "42",
                                         "compiled toygroup triple"]
    assert first.stderr == "camlab88: compiling toy kernels, once: ~1 s\n"
    second = _run(tmp_path, "import toygroup\nprint(toygroup.triple(2))\n")
    assert second.returncode == 0, second.stderr
    assert second.stdout.splitlines() == ["6"]  # loaded from the cache: no compile event
    assert second.stderr == ""


def test_a_failing_completion_is_reported_and_the_exit_status_kept(tmp_path: Path) -> None:
    code = """
    import sys, toygroup
    toygroup.complete = lambda: 1 / 0
    print(toygroup.double(2))
    sys.exit(3)
    """
    done = _run(tmp_path, code)
    assert done.returncode == 3
    assert "the rest of the toy kernels were not compiled ahead (ZeroDivisionError" in done.stderr


def test_the_sigma_streams_share_one_compile(tmp_path: Path) -> None:
    """After a T5684 stream of plain vectors, the T5688's GKS stream (abbreviated polylines,
    other kernels) compiles nothing."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(ROOT))
    cmd = [sys.executable, "-m", "camlab88", "sigma", "render"]
    first = subprocess.run(cmd + ["--in", str(ROOT / "examples/sigma/pgplot_goc.sig"),
                                  "--out", str(tmp_path / "a.png")],
                           env=env, capture_output=True, text=True, timeout=300)
    assert first.returncode == 0, first.stderr
    assert "compiling Sigma raster kernels" in first.stderr
    second = subprocess.run(cmd + ["--model", "t5688", "--in",
                                   str(ROOT / "examples/sigma/ral_gks_t5688.sig"),
                                   "--out", str(tmp_path / "b.png")],
                            env=env, capture_output=True, text=True, timeout=300)
    assert second.returncode == 0, second.stderr
    assert "compiling" not in second.stderr


def test_the_rainbow_group_compiles_whole(tmp_path: Path) -> None:
    """A program that only compiles band structures (no frame shown) leaves the video
    processor's scan-out compiled too: the next program's frame compiles nothing."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(ROOT))
    device = ("from camlab88.emulator.rainbow import Rainbow\n"
              "r = Rainbow(); p = r.create_pad(20, 20, 1); r.map(r.screen, p, 5, 5)\n")
    first = subprocess.run([sys.executable, "-c", PRINT_COMPILES + device + "r.bands()\n"],
                           env=env, capture_output=True, text=True, timeout=300)
    assert first.returncode == 0, first.stderr
    notices = first.stderr.splitlines()
    assert len(notices) == 1 and notices[0].startswith("camlab88: compiling Rainbow kernels")
    # at exit
    assert "compiled camlab88.emulator.rainbow._kernels scanout" in first.stdout.splitlines()
    second = subprocess.run([sys.executable, "-c", PRINT_COMPILES + device + "r.frame()\n"],
                            env=env, capture_output=True, text=True, timeout=300)
    assert second.returncode == 0, second.stderr
    assert second.stdout == "" and second.stderr == ""
