"""A film's first run on a cold numba cache compiles the renderer's kernels once, in the
command's own process, under one notice: the pool's workers load them from the cache instead
of each compiling them (and each printing the notice)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_a_cold_film_on_two_workers_compiles_the_renderer_once(tmp_path: Path) -> None:
    env = dict(os.environ, PYTHONPATH=str(ROOT), NUMBA_CACHE_DIR=str(tmp_path / "cache"),
               SDL_VIDEODRIVER="dummy")
    done = subprocess.run(
        [sys.executable, "-m", "camlab88", "ca", "film", "life", "glider", "--actors",
         str(ROOT / "examples" / "ca" / "chess.actors"), "--generations", "1",
         "--frames-per-generation", "2", "--size", "96x64", "--workers", "2",
         "--out", str(tmp_path / "glider.gif")],
        cwd=tmp_path, env=env, capture_output=True, text=True, timeout=900, check=False)
    assert done.returncode == 0, done.stderr
    notices = [line for line in done.stderr.splitlines()
               if line.startswith("camlab88: compiling actors renderer")]
    assert len(notices) == 1, done.stderr
