"""The command line as a process: it loads only the area it runs, and it ends without the
interpreter's module-by-module teardown (after numba that costs as much CPU as a short
command), yet atexit handlers still run and all output arrives."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from camlab88.cli import build_parser
from tests.support.processes import fresh_python

ROOT = Path(__file__).resolve().parents[2]

_SCRIPT = """
import atexit, sys
from camlab88 import cli

class Noisy:
    def __del__(self):
        sys.stderr.write("torn down\\n")

keep = Noisy()
atexit.register(lambda: print("atexit ran"))
sys.argv = ["camlab88", *sys.argv[1:]]
raise SystemExit(cli.main())
"""


def _program(*words: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run([sys.executable, "-c", _SCRIPT, *words], capture_output=True,
                          text=True, timeout=120, env=env, cwd=ROOT)


def test_the_program_ends_without_tearing_down_the_interpreter() -> None:
    result = _program("ca", "run", "--rules", "life", "--pattern", "glider",
                      "--generations", "4")
    assert result.returncode == 0, result.stderr
    assert "generation 4  population 5" in result.stdout
    assert result.stdout.rstrip().endswith("atexit ran")
    assert "torn down" not in result.stderr


def test_the_exit_status_survives_the_quick_end(tmp_path: Path) -> None:
    result = _program("ca", "run", "--rules", "life", "--generations", "1", "--pattern",
                      str(tmp_path / "missing.rle"))
    assert result.returncode == 2
    assert "missing.rle" in result.stderr


def test_a_command_loads_only_its_own_area() -> None:
    words = ["ca", "run", "--rules", "life", "--pattern", "glider", "--generations", "0"]
    code = (f"import sys; from camlab88.cli import main; main({words!r}); "
            "print(sorted(m for m in sys.modules if m.startswith('camlab88.commands.')"
            " and m.count('.') == 2))")
    assert fresh_python(code, cwd=ROOT).splitlines()[-1] == "['camlab88.commands.ca']"


def test_the_area_parser_and_the_whole_parser() -> None:
    whole = next(a for a in build_parser()._actions if a.dest == "command")
    assert {"ca", "snooker", "kas", "demo"} <= set(whole.choices)
    one = next(a for a in build_parser(["ca", "run"])._actions if a.dest == "command")
    assert set(one.choices) == {"ca"}
    misspelt = next(a for a in build_parser(["snoker"])._actions if a.dest == "command")
    assert "snooker" in misspelt.choices
