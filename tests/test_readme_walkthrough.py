"""README's "First ten minutes": its commands, taken from README.md itself (so the two
cannot drift), run in order in a fresh directory, headless, each succeeding and writing the
files it names for the next."""

from __future__ import annotations

import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SECTION = "## First ten minutes"
OUTPUT_OPTIONS = ("--out", "--save-session", "--path-out", "--timing-out", "--png", "--log",
                  "--bands", "--pdf")


def walkthrough_commands(readme: str) -> list[list[str]]:
    """The indented `camlab88 ...` lines of the section, in order, split as a shell would."""
    start = readme.index(SECTION + "\n")
    end = readme.find("\n## ", start + len(SECTION))
    body = readme[start:end if end >= 0 else len(readme)]
    return [shlex.split(line.strip(), comments=True) for line in body.splitlines()
            if line.startswith("    camlab88 ")]


def _camlab88() -> list[str]:
    script = Path(sys.executable).with_name("camlab88")
    return [str(script)] if script.exists() else [sys.executable, "-m", "camlab88"]


def _outputs(argv: list[str]) -> list[str]:
    return [argv[i + 1] for i, a in enumerate(argv[:-1]) if a in OUTPUT_OPTIONS]


def test_the_section_lists_the_whole_tour() -> None:
    commands = walkthrough_commands((ROOT / "README.md").read_text(encoding="utf-8"))
    areas = {argv[1] for argv in commands}
    assert {"sigma", "rainbow", "kas", "snooker", "ca"} <= areas
    assert len(commands) >= 15


def test_the_walkthrough_runs_in_order(tmp_path: Path) -> None:
    commands = walkthrough_commands((ROOT / "README.md").read_text(encoding="utf-8"))
    shutil.copytree(ROOT / "examples", tmp_path / "examples")  # the README's relative paths
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env.update(SDL_VIDEODRIVER="dummy", CAMLAB88_KAS_LIBRARY=str(tmp_path / "library"),
               XDG_DATA_HOME=str(tmp_path / "data"))
    for argv in commands:
        done = subprocess.run(_camlab88() + argv[1:], cwd=tmp_path, env=env, text=True,
                              capture_output=True, timeout=300)
        shown = " ".join(argv)
        assert done.returncode == 0, f"{shown}\n{done.stdout}\n{done.stderr}"
        assert "Traceback" not in done.stderr, f"{shown}\n{done.stderr}"
        for name in _outputs(argv):
            assert (tmp_path / name).exists(), f"{shown} did not write {name}"
    assert (tmp_path / "library" / "my_arc.kas").is_file()  # kas library --save kept it
    assert (tmp_path / "plots" / "sequence.pdf").is_file()
    assert (tmp_path / "house_sun.gif").stat().st_size > 0
    # the examples themselves are inputs only: nothing in the walkthrough rewrote them
    for shipped in (ROOT / "examples").rglob("*"):
        if shipped.is_file():
            copy = tmp_path / "examples" / shipped.relative_to(ROOT / "examples")
            assert copy.read_bytes() == shipped.read_bytes(), copy
