"""Runs nobody can answer end (issue 45's "runs that never end"): `snooker camera ...
--headless --screenshot` ran until killed; `ca program --script LOG --screenshot` sat on
"Script: begin at which generation?"; `ca program --script LOG --headless` without
`--start` ran an empty world. Each runs here as a user types it, in a process of its own
under a time limit (a window on SDL's dummy driver where the user had a display)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
LIMIT_S = 240  # a first run compiles kernels; a hang is what fails


def _camlab88(tmp: Path, *argv: str, window: bool = False) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER")}
    if window:
        env["SDL_VIDEODRIVER"] = "dummy"
    return subprocess.run([sys.executable, "-m", "camlab88", *argv], cwd=tmp, env=env,
                          stdin=subprocess.DEVNULL, capture_output=True, text=True,
                          timeout=LIMIT_S)


@pytest.fixture
def glider_log(tmp_path: Path) -> Path:
    done = _camlab88(tmp_path, "ca", "program", "--headless", "--pattern", "glider",
                     "--events", str(ROOT / "examples" / "ca" / "session.events"),
                     "--log", "session.log", "--record-pans")
    assert done.returncode == 0, done.stderr
    return tmp_path / "session.log"


@pytest.mark.parametrize("window", [False, True])
def test_a_script_without_start_begins_at_the_logs_first_generation(glider_log: Path,
                                                                    window: bool) -> None:
    tmp = glider_log.parent
    extra = ["--screenshot", "caprog.png"] if window else ["--headless"]
    done = _camlab88(tmp, "ca", "program", "--script", "session.log", *extra, window=window)
    assert done.returncode == 0, done.stderr
    assert "beginning the script at generation 0, the Log's first" in done.stderr
    population = int(done.stdout.split("population")[1].split()[0])
    assert population > 0, done.stdout  # not the empty world of a question never answered
    if window:
        assert (tmp / "caprog.png").is_file()


def test_a_script_with_start_asks_nothing_and_says_nothing(glider_log: Path) -> None:
    done = _camlab88(glider_log.parent, "ca", "program", "--script", "session.log",
                     "--headless", "--start", "4")
    assert done.returncode == 0, done.stderr
    assert "Log's first" not in done.stderr
    assert "generation 4" in done.stdout


@pytest.mark.parametrize("window", [False, True])
def test_the_camera_tool_with_a_screenshot_ends(tmp_path: Path, window: bool) -> None:
    data = ROOT / "tests" / "data" / "snooker_camera"
    shutil.copy(data / "thesis_example.ccl", tmp_path / "my.ccl")
    extra = ["--screenshot", "c2.png"] + ([] if window else ["--headless"])
    done = _camlab88(tmp_path, "snooker", "camera", "my.ccl",
                     str(data / "pink_shot.session.json"), *extra, window=window)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "c2.png").is_file()
    assert "100 frames shown" in done.stderr
