"""One exit-status rule for every command (docs/exit_status.md): 0 done, 1 the work
started and failed, 2 it could not start on what it was given — here, a missing input file
and an output that cannot be written — with one line on stderr naming the file and no
traceback. Run as a user runs them: one process each, ``python -m camlab88``."""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
from pathlib import Path

import pytest

from camlab88.cli import build_parser

ROOT = Path(__file__).resolve().parents[1]
M = "missing.input"
STREAM = str(ROOT / "examples" / "sigma" / "pgplot_goc.sig")
SCENE = str(ROOT / "examples" / "rainbow" / "scene.json")
CHECKPOINT = str(ROOT / "tests" / "data" / "snooker_camera" / "pink_shot.checkpoint")
CCL = str(ROOT / "tests" / "data" / "snooker_camera" / "thesis_example.ccl")
LINE_REC = "camlab88-link-recording 1\nline 9600 8N1\nxonxoff on\n0.010000 > 48\nend 1\n"

# every command: an argv naming a missing input, or why it has none
MISSING: dict[str, list[str] | str] = {
    "demo": "no input file",
    "warm-up": "no input file",
    "sigma render": ["--in", M, "--out", "o.png"],
    "sigma run": ["--headless", "--in", M, "--seconds", "1"],
    "rainbow render": [M, "--out", "o.png"],
    "rainbow run": "reads no file (a scene comes over --listen)",
    "rainbow serve": "no input file",
    "rainbow replay": [M],
    "tablet list": "no input file",
    "tablet monitor": "a SOURCE names a device, not a file",
    "tablet calibrate": "a SOURCE names a device, not a file",
    "tablet emulate": "no input file",
    "link dump": [M],
    "link stream": [M, "--out", "o.bin"],
    "link echo": "no input file",
    "kas inbetween": [M, "walk_b", "--out", "o.kas"],
    "kas superimpose": [M, "--out", "o.kas"],
    "kas plot": [M, "--pdf", "plots"],
    "kas export": [M, "o.gif"],
    "kas schedule": "its input is frame sizes on the command line",
    "kas edit-script": [M, "--out", "o.kas"],
    "kas path-script": [M, "walk_b", "examples/kas/arc.script", "--path-out", "p.kas",
                        "--timing-out", "t.kas"],
    "kas edit": ["o.kas", "--headless", "--script", M],
    "kas path": [M, "walk_b", "--out", "p.kas", "--headless"],
    "kas view": [M, "--headless"],
    "kas paint": [M, "--headless"],
    "kas library": ["--save", M, "x"],
    "kas demo": "no input file",
    "snooker play": "a missing SESSION is a new game, saved there",
    "snooker simulate": ["--from", M, "--shot", "cue", "1", "0", "--out", "o.cp"],
    "snooker replay": [M, "--headless"],
    "snooker ccl": [M, CHECKPOINT, "--out", "o.views"],
    "snooker visualise": [M, "o.views", "--headless"],
    "snooker camera": [CCL, M, "--headless"],
    "snooker render": [M, "o.views", "--frames", "f"],
    "snooker film": [M, CCL, "--out", "o.mp4"],
    "ca run": ["--rules", M, "--pattern", "glider", "--generations", "3"],
    "ca convert": [M, "o.cells"],
    "ca replay": ["--script", M, "--generation", "3"],
    "ca program": ["--headless", "--pattern", M],
    "ca library": "no input file",
    "ca film": ["life", "glider", "--actors", M, "--generations", "1", "--out", "o.gif"],
    "ca actors": ["new.actors", "--headless", "--events", M],
    "replay": [M],
    "figures": "its argument is a figure number (an unknown one: 2, tests/test_figures.py)",
}

# commands that write a file: an argv whose output path cannot be written ({BAD} is a path
# under a plain file, which no user, root included, can create)
UNWRITABLE: dict[str, list[str]] = {
    "sigma render": ["--in", STREAM, "--out", "{BAD}.png"],
    "rainbow render": [SCENE, "--out", "{BAD}.png"],
    "link stream": ["line.rec", "--out", "{BAD}.bin"],
    "kas inbetween": ["sun_a", "sun_b", "--frames", "3", "--out", "{BAD}.kas"],
    "kas export": ["sun.kas", "{BAD}.gif"],
    "kas edit-script": ["examples/kas/house.script", "--out", "{BAD}.kas"],
    "snooker simulate": ["--break", "1", "--out", "{BAD}.cp"],
    "snooker ccl": [CCL, CHECKPOINT, "--out", "{BAD}.views"],
    "ca run": ["--rules", "life", "--pattern", "glider", "--generations", "1",
               "--png", "{BAD}.png"],
    "ca convert": ["glider", "{BAD}.cells"],
    "ca film": ["life", "glider", "--generations", "1", "--size", "16x16", "--out",
                "{BAD}.gif"],
    "ca actors": ["{BAD}.actors", "--headless", "--stop-after", "1"],
}


def _commands() -> list[str]:
    """Every runnable command of the parser, as "area action" (or a bare command)."""
    found: list[str] = []

    def walk(parser: argparse.ArgumentParser, prefix: list[str]) -> None:
        subs = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
        if not subs:
            found.append(" ".join(prefix))
        for action in subs:
            for name, sub in action.choices.items():
                walk(sub, [*prefix, name])

    walk(build_parser(), [])
    return found


def _run(tmp_path: Path, argv: list[str]) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env.update(PYTHONPATH=str(ROOT), SDL_VIDEODRIVER="dummy",
               CAMLAB88_KAS_LIBRARY=str(tmp_path / "library"))
    (tmp_path / "examples").exists() or (tmp_path / "examples").symlink_to(ROOT / "examples")
    return subprocess.run([sys.executable, "-m", "camlab88", *argv], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL)


def test_every_command_is_covered() -> None:
    assert sorted(_commands()) == sorted(MISSING)


@pytest.mark.parametrize("command", [c for c, v in MISSING.items() if isinstance(v, list)])
def test_a_missing_input_is_a_usage_error(tmp_path: Path, command: str) -> None:
    done = _run(tmp_path, [*command.split(), *MISSING[command]])
    assert done.returncode == 2, (done.returncode, done.stderr)
    assert M in done.stderr and "Traceback" not in done.stderr, done.stderr


@pytest.mark.parametrize("command", sorted(UNWRITABLE))
def test_an_output_that_cannot_be_written_is_a_usage_error(tmp_path: Path,
                                                           command: str) -> None:
    (tmp_path / "plain").write_text("a file, not a directory\n")
    (tmp_path / "line.rec").write_text(LINE_REC)
    if command == "kas export":  # a sequence to export
        assert _run(tmp_path, ["kas", "inbetween", "sun_a", "sun_b", "--frames", "3",
                               "--out", "sun.kas"]).returncode == 0
    bad = str(tmp_path / "plain" / "out")
    done = _run(tmp_path, [*command.split(), *(a.replace("{BAD}", bad)
                                               for a in UNWRITABLE[command])])
    assert done.returncode == 2, (done.returncode, done.stderr)
    assert "plain" in done.stderr and "Traceback" not in done.stderr, done.stderr


def test_a_directory_given_as_a_recording_is_named_plainly(tmp_path: Path) -> None:
    """`camlab88 replay examples` (a directory): the file's name, not `examples:0:0`."""
    done = _run(tmp_path, ["replay", "examples"])
    assert done.returncode == 2
    assert done.stderr.strip() == "camlab88 replay: examples: cannot read: Is a directory"
