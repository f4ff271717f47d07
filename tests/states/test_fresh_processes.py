"""A state saved by one process and loaded by another continues with the frames of the
uninterrupted run, for the programs that declare their state and that test_state_files.py
leaves out (kas view, snooker replay, snooker visualise, ca program, sigma run, rainbow
run): ``--frames all`` of a run that saves at ``--at T`` against ``--frames rest`` of a new
process that loads it."""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from tests.states.support import ROOT, inputs_of


def _cli(args: list[str], cwd: Path) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PYTHONPATH=str(ROOT), SDL_VIDEODRIVER="dummy")
    return subprocess.run([sys.executable, "-m", "camlab88", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600, check=False)


def _kas_view(d: Path) -> list[str]:
    made = _cli(["kas", "demo", "--out", "seq.kas"], d)
    assert made.returncode == 0, made.stderr
    return ["kas", "view", "seq.kas", "--headless", "--every"]


def _ca_program(d: Path) -> list[str]:
    (d / "e.events").write_text("frames 3\nclick left 300 200\nframes 4\nkey space\n"
                                "frames 12\n")
    return ["ca", "program", "--headless", "--pattern", "gosper_gun", "--events", "e.events"]


PROGRAMS: dict[str, tuple[Callable[[Path], list[str]], str]] = {
    "snooker-replay": (lambda d: ["snooker", "replay", "pink_shot.cp", "--headless"], "1"),
    "kas-view": (_kas_view, "1"),
    "snooker-visualise": (lambda d: ["snooker", "visualise", "pink_shot.cp", "example.views",
                                     "--headless"], "1"),
    "ca-program": (_ca_program, "0.2"),
    "sigma-run": (lambda d: ["sigma", "run", "--headless", "--in", "picture.sigma",
                             "--seconds", "2"], "1"),
    "rainbow-run": (lambda d: ["rainbow", "run", "--headless", "--stop-after", "30", "--demo",
                               "pads"], "0.5"),
}
INPUTS = {"snooker-replay": "examples/figures/fig-6.7.session",
          "snooker-visualise": "examples/figures/fig-6.7.session",
          "sigma-run": "tests/data/sessions/sigma_run.session"}


def _pngs(d: Path) -> list[bytes]:
    return [p.read_bytes() for p in sorted(d.glob("frame_*.png"))]


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_a_state_saved_by_one_process_continues_in_another(tmp_path: Path, name: str) -> None:
    if name in INPUTS:
        inputs_of(INPUTS[name], tmp_path)
    make, at = PROGRAMS[name]
    argv = make(tmp_path)
    first = _cli([*argv, "--frames", "all", "--save-state", "s.c88state", "--at", at],
                 tmp_path)
    assert first.returncode == 0, first.stderr
    assert (tmp_path / "s.c88state").is_file(), first.stderr
    second = _cli([*argv, "--frames", "rest", "--load-state", "s.c88state"], tmp_path)
    assert second.returncode == 0, second.stderr
    everything, rest = _pngs(tmp_path / "all"), _pngs(tmp_path / "rest")
    assert 0 < len(rest) < len(everything), (len(rest), len(everything))
    assert rest == everything[len(everything) - len(rest):]
