"""`camlab88 snooker ccl / visualise / camera`, end to end through the console entry point."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import numpy as np
from PIL import Image

from camlab88.apps.snooker.camera.views import read_views
from camlab88.cli import main

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker_camera"
SHOT = str(DATA / "pink_shot.checkpoint")


def test_ccl_writes_the_view_file(tmp_path: Path, capsys) -> None:
    out = tmp_path / "ex.views"
    assert main(["snooker", "ccl", str(DATA / "thesis_example.ccl"), SHOT, "--out",
                 str(out)]) == 0
    views = read_views(out)
    assert [v.frame for v in views] == list(range(1, 76))
    assert views[0].observer == (-5.5, 0.0, 2.5) and views[74].focal_mm == 28.0
    assert "wrote 75 frames" in capsys.readouterr().out


def test_ccl_reports_every_error_and_writes_nothing(tmp_path: Path, capsys) -> None:
    script = tmp_path / "bad.ccl"
    script.write_text(":\nveiwpoint at (0,0,0);\nfocal length of 3\n:from 60 until pink ball "
                      "starts\n")
    out = tmp_path / "x.views"
    assert main(["snooker", "ccl", str(script), str(DATA / "pink_shot.session.json"), "--out",
                 str(out)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert [e.split(": ")[0] for e in err[:3]] == [f"{script}:2:1", f"{script}:3:17",
                                                   f"{script}:4:16"]
    assert "3 errors; no view file written" in err[3] and not out.exists()


def test_ccl_names_a_bad_checkpoint(tmp_path: Path, capsys) -> None:
    bad = tmp_path / "bad.cp"
    bad.write_text("1,2\n")
    assert main(["snooker", "ccl", str(DATA / "thesis_example.ccl"), str(bad), "--out",
                 str(tmp_path / "v")]) == 2
    assert f"{bad}:" in capsys.readouterr().err


def test_visualise_writes_frames_numbered_as_the_checkpoint(tmp_path: Path) -> None:
    views = tmp_path / "v.views"
    lines = (DATA / "thesis_example.ccl").read_text()
    (tmp_path / "s.ccl").write_text(lines)
    assert main(["snooker", "ccl", str(tmp_path / "s.ccl"), SHOT, "--out", str(views)]) == 0
    part = tmp_path / "part.views"  # frames 40..44 only
    text = views.read_text().splitlines()
    part.write_text("\n".join(t for t in text if t.split()[0] in ("40", "41", "42", "43", "44"))
                    + "\n")
    frames = tmp_path / "frames"
    assert main(["snooker", "visualise", SHOT, str(part), "--headless", "--frames",
                 str(frames)]) == 0
    names = sorted(p.name for p in frames.iterdir())
    assert names == [f"frame_{n:05d}.png" for n in range(40, 45)]
    a = np.asarray(Image.open(frames / "frame_00040.png"))
    b = np.asarray(Image.open(frames / "frame_00044.png"))
    assert a.shape == (576, 768, 3) and not np.array_equal(a, b)


def test_camera_tool_headless_with_scripted_input(tmp_path: Path, capsys) -> None:
    script = tmp_path / "cam.ccl"
    shutil.copy(DATA / "thesis_example.ccl", script)
    events = tmp_path / "ev.txt"
    events.write_text("wait 2\nkey down\nkey down\nkey down\ntype veiw\nwait 2\n")
    shot = tmp_path / "shot.png"
    assert main(["snooker", "camera", str(script), SHOT, "--events", str(events),
                 "--headless", "--screenshot", str(shot)]) == 0
    assert "1 error now; unsaved edits" in capsys.readouterr().err and shot.exists()


def test_a_recorded_session_replays_the_script_saved_from_outside(tmp_path: Path,
                                                                  monkeypatch) -> None:
    import argparse

    from camlab88.apps.snooker.camera import motion
    from camlab88.commands.snooker import camera as command
    from camlab88.emulator.harness.loop import Plugin
    from camlab88.runopts import run_options

    monkeypatch.chdir(tmp_path)
    shutil.copy(DATA / "thesis_example.ccl", "cam.ccl")
    shutil.copy(SHOT, "shot.cp")
    argv = ["snooker", "camera", "cam.ccl", "shot.cp", "--headless", "--stop-after", "12",
            "--record", "rec.jsonl"]
    args = argparse.Namespace(headless=True, screenshot=None, frames=None, stop_after=12,
                              record=Path("rec.jsonl"), scale=1)
    opts = run_options(args, command.COMMAND, "test", argv=argv)

    class Editor(Plugin):  # another editor saves the script while the tool runs
        def post_tick(self, harness) -> None:
            if harness.ticks == 5:
                Path("cam.ccl").write_text(":focal length of 300\n")
                os.utime("cam.ccl", ns=(1, 3))

    _, tool = command._run(motion.load("shot.cp"), "cam.ccl", None, opts, [Editor()])
    assert tool.result.focal[0] == 300
    Path("cam.ccl").write_text((DATA / "thesis_example.ccl").read_text())  # as at the start
    assert main(["replay", "rec.jsonl", "--headless", "--check"]) == 0


def test_readme_camera_tool_command(tmp_path: Path, capsys) -> None:
    """The README's camera-tool screenshot command, headless, with the shipped events."""
    script = tmp_path / "example.ccl"
    shutil.copy(DATA / "thesis_example.ccl", script)
    shot = tmp_path / "tool.png"
    assert main(["snooker", "camera", str(script), SHOT, "--events",
                 str(DATA / "typo.events"), "--headless", "--screenshot", str(shot)]) == 0
    assert "1 error now; unsaved edits" in capsys.readouterr().err
    img = np.asarray(Image.open(shot).convert("RGB"))
    assert img.shape == (576, 768, 3)
    assert script.read_text() == (DATA / "thesis_example.ccl").read_text()  # not saved
