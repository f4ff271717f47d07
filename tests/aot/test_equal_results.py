"""Every module compiled ahead of time gives the JIT path's results on real runs, and a
process whose kernels all come from the extensions never imports numba."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import types
from pathlib import Path

import pytest

from camlab88.base import aot_load
from camlab88.commands.warmup.aot import AOT_MODULES

ROOT = Path(__file__).resolve().parents[2]
RUNS = Path(__file__).with_name("runs.py")
NO_NUMBA = ("import sys\nfrom camlab88.cli import main\nrc = main({argv!r})\n"
            "print(rc, 'numba' in sys.modules, file=sys.stderr)\n")


def _env(aot_dir: Path, aot: bool) -> dict[str, str]:
    env = dict(os.environ, PYTHONPATH=str(ROOT), **{aot_load.DIR_VARIABLE: str(aot_dir)})
    env[aot_load.OFF_VARIABLE] = "1" if aot else "0"
    return env


def _python(args: list[str], env: dict[str, str], cwd: Path) -> subprocess.CompletedProcess:
    done = subprocess.run([sys.executable, *args], env=env, cwd=cwd, capture_output=True,
                          text=True, timeout=900)
    assert done.returncode == 0, done.stderr
    return done


def test_every_kernel_gives_the_jit_result(aot_dir: Path, tmp_path: Path) -> None:
    both = {}
    for aot in (True, False):
        done = _python([str(RUNS), *AOT_MODULES], _env(aot_dir, aot), tmp_path)
        both[aot] = json.loads(done.stdout)
    aot, jit = both[True], both[False]
    assert set(aot["modes"].values()) == {"aot"} and set(jit["modes"].values()) == {"jit"}
    assert aot["numba"] is False and jit["numba"] is True
    assert aot["u16 messages"] == "uint16"
    assert {k for used in aot["kernels"].values() for k in used} == {"window", "hash", "dense"}
    assert aot["cases"] == jit["cases"]
    assert aot["kernels"] == jit["kernels"]


@pytest.mark.parametrize("argv", [
    ["ca", "run", "--rules", "life", "--pattern", "acorn", "--generations", "5206",
     "--engine", "direct", "--json"],
    ["ca", "run", "--rules", "life", "--pattern", "gosper_gun", "--generations", "300",
     "--engine", "direct", "--json", "--edges", "wrap"],
    # HashLife: bit leaves (Life, both edges) and value leaves (a multi-state rule table)
    ["ca", "run", "--rules", "life", "--pattern", "acorn", "--generations", "5206",
     "--engine", "hashlife", "--json"],
    ["ca", "run", "--rules", "life", "--pattern", "gosper_gun", "--generations", "100000",
     "--engine", "hashlife", "--json", "--edges", "wrap"],
    ["ca", "run", "--rules", "turing_primes", "--pattern", "primes_25", "--generations",
     "4096", "--engine", "hashlife", "--json"],
])
def test_ca_run_prints_the_same_without_numba(aot_dir: Path, tmp_path: Path,
                                               argv: list[str]) -> None:
    out = {}
    for aot in (True, False):
        done = _python(["-c", NO_NUMBA.format(argv=argv)], _env(aot_dir, aot), tmp_path)
        out[aot] = done.stdout
        assert done.stderr.splitlines()[-1] == f"0 {not aot}"
    assert out[True] == out[False] and '"population"' in out[True]


def test_an_edited_module_is_not_loaded(aot_dir: Path, tmp_path: Path, monkeypatch) -> None:
    """The key covers the module's source: a byte-for-byte copy finds the extension, the
    copy with one more line does not (so its kernels would be JIT-compiled)."""
    monkeypatch.setenv(aot_load.DIR_VARIABLE, str(aot_dir))
    monkeypatch.setenv(aot_load.OFF_VARIABLE, "1")
    name = "camlab88.apps.ca.grid_stats"
    copy = tmp_path / "grid_stats.py"
    copy.write_text((ROOT / "apps/ca/grid_stats.py").read_text())
    monkeypatch.setitem(sys.modules, name, types.SimpleNamespace(__file__=str(copy)))
    extension, why = aot_load.load(name)
    assert extension is not None and why == ""
    with copy.open("a") as fh:
        fh.write("# edited\n")
    assert aot_load.load(name) == (None, "not built for these sources")


def test_an_unloadable_extension_means_the_jit_path(aot_dir: Path, tmp_path: Path) -> None:
    broken = tmp_path / "aot"
    broken.mkdir()
    for built in aot_dir.glob("camlab88.apps.ca.grid_stats-*"):
        (broken / built.name).write_bytes(b"not an ELF file")
    code = ("import numpy as np\nimport camlab88.apps.ca.grid_stats as g\n"
            "print(g.kernels.mode, g.kernels.why_jit.split()[0], "
            "g.by_type(np.array([[0, 2], [2, 7]], np.uint8)))\n")
    done = _python(["-c", code], _env(broken, True), tmp_path)
    assert done.stdout == "jit not {2: 2, 7: 1}\n"
    off = _python(["-c", code], _env(aot_dir, False), tmp_path)
    assert off.stdout == "jit CAMLAB88_AOT {2: 2, 7: 1}\n"


def test_a_second_build_finds_everything_up_to_date(aot_dir: Path) -> None:
    from camlab88.base import aot_build

    assert aot_build.build(AOT_MODULES, aot_dir) == {m: aot_build.UP_TO_DATE
                                                      for m in AOT_MODULES}
