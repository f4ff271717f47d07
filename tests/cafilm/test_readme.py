"""The README's `ca film` commands run as printed (taken from README.md itself), each
writing the film it names and its frames."""

from __future__ import annotations

import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SECTION = "## The cellular automaton in 3-D: cells as actors"


def _commands() -> list[list[str]]:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    start = text.index(SECTION)
    end = text.index("\n## ", start + len(SECTION))
    return [shlex.split(line.strip()) for line in text[start:end].splitlines()
            if line.startswith(("    camlab88 ca film ", "    mkdir -p "))]
    # (the editor's subsection has its own test)


def test_the_section_shows_truecolour_and_period_films() -> None:
    cmds = [c for c in _commands() if c[0] == "camlab88"]
    assert len(cmds) >= 3 and all(c[1:3] == ["ca", "film"] for c in cmds)
    assert any("t5688" in c for c in cmds) and any("gosper_gun" in c for c in cmds)


def test_the_readme_film_commands_run_as_printed(tmp_path: Path) -> None:
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    for argv in _commands():
        if argv[0] == "mkdir":  # as printed: an output's directory is never made for it
            for folder in argv[2:]:
                (tmp_path / folder).mkdir(parents=True, exist_ok=True)
            continue
        done = subprocess.run([sys.executable, "-m", "camlab88", *argv[1:]], cwd=tmp_path,
                              env=env, text=True, capture_output=True, timeout=600)
        shown = " ".join(argv)
        assert done.returncode == 0, f"{shown}\n{done.stderr}"
        assert "Traceback" not in done.stderr, f"{shown}\n{done.stderr}"
        out = tmp_path / argv[argv.index("--out") + 1]
        assert out.stat().st_size > 0, shown
        assert any(out.with_name(f"{out.stem}_frames").glob("frame_*.png")), shown
