"""``camlab88 snooker render``: frames numbered as the checkpoint's, bad inputs named by
file:line, nothing half-written."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from camlab88.cli import main
from tests.snooker_render.helpers import BREAK, VIEWS

ARGS = ["snooker", "render", str(BREAK), str(VIEWS)]


def test_truecolour_frames_numbered_as_the_checkpoint(tmp_path: Path) -> None:
    out = tmp_path / "frames"
    assert main([*ARGS, "--frames", str(out), "--mode", "truecolour", "--size", "96x64",
                 "--first", "7", "--last", "9"]) == 0
    # the resume record is hidden among the frames (test_parallel); the rest is frames only
    names = sorted(p.name for p in out.iterdir() if not p.name.startswith("."))
    assert names == [f"frame_0000{k}.png" for k in (7, 8, 9)]
    with Image.open(out / "frame_00008.png") as im:
        assert im.size == (96, 64)


def test_period_frame_is_the_terminal_screen(tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "p"
    assert main([*ARGS, "--frames", str(out), "--first", "3", "--last", "3"]) == 0
    with Image.open(out / "frame_00003.png") as im:
        img = np.asarray(im)
    assert img.shape == (512, 768, 3)
    err = capsys.readouterr().err
    assert "line time" in err and "leaking pixels" in err


def test_bad_view_file_names_its_line_and_writes_nothing(tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]
                                                         ) -> None:
    bad = tmp_path / "bad.views"
    bad.write_text(VIEWS.read_text().replace("\n3 ", "\n3 oops ", 1))
    out = tmp_path / "f"
    assert main(["snooker", "render", str(BREAK), str(bad), "--frames", str(out),
                 "--mode", "truecolour", "--size", "32x32"]) == 2
    assert f"{bad}:4:" in capsys.readouterr().err
    assert not out.exists() or not any(out.iterdir())


def test_bad_lights_file_and_checkpoint(tmp_path: Path,
                                       capsys: pytest.CaptureFixture[str]) -> None:
    lights = tmp_path / "l.txt"
    lights.write_text("0 0 1\n0 0 high\n")
    assert main([*ARGS, "--frames", str(tmp_path / "x"), "--lights", str(lights)]) == 2
    assert f"{lights}:2:5:" in capsys.readouterr().err
    cp = tmp_path / "c.checkpoint"
    cp.write_text("1,2\n")
    assert main(["snooker", "render", str(cp), str(VIEWS), "--frames", str(tmp_path / "y")]) == 2
    assert f"{cp}:" in capsys.readouterr().err


def test_frames_outside_the_views_are_refused(tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    assert main([*ARGS, "--frames", str(tmp_path / "z"), "--first", "39", "--last", "41"]) == 2
    assert "no view for frame 41" in capsys.readouterr().err
