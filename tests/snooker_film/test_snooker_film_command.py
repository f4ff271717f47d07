"""`camlab88 snooker film`: script -> views -> frames -> MP4 and GIF, intermediates kept
beside the film, a second run renders nothing, a bad script renders nothing."""

from __future__ import annotations

from pathlib import Path

import imageio.v3 as iio
import pytest

from camlab88.cli import main
from tests.snooker_film.helpers import BREAK, SCRIPT


@pytest.mark.claim(
    "§6.4: after the motion and the camera angles, high quality frames are rendered and "
    "compiled into a finished sequence",
    measured="one command: camera script -> views -> 40 rendered frames -> a 25 frames/s MP4 "
             "and GIF; a second run renders nothing",
    verdict="agrees (a video file stands in for the single-frame video device or movie camera)")
def test_the_pipeline_in_one_command(tmp_path: Path, capsys) -> None:
    out = tmp_path / "shot.mp4"
    args = ["snooker", "film", str(BREAK), str(SCRIPT), "--out", str(out), "--gif",
            str(tmp_path / "shot.gif"), "--size", "48x32", "--workers", "1"]
    assert main(args) == 0
    assert (tmp_path / "shot.views").read_text().count("\n") > 40
    frames = sorted((tmp_path / "shot_frames").glob("frame_*.png"))
    assert [f.name for f in frames[:2]] == ["frame_00001.png", "frame_00002.png"]
    assert len(frames) == 40
    gif = iio.imread(tmp_path / "shot.gif")
    assert gif.shape == (40, 32, 48, 3)
    meta = iio.immeta(out)
    assert round(meta["fps"]) == 25 and "audio_codec" not in meta
    assert "40 rendered, 0 already there" in capsys.readouterr().err
    assert main(args) == 0
    assert "0 rendered, 40 already there" in capsys.readouterr().err


def test_a_bad_script_renders_nothing(tmp_path: Path, capsys) -> None:
    bad = tmp_path / "bad.ccl"
    bad.write_text(":\nfrom frame 1 until frame 40;\nobserver at (1, 2);\n")
    code = main(["snooker", "film", str(BREAK), str(bad), "--out", str(tmp_path / "s.mp4")])
    err = capsys.readouterr().err
    assert code == 2 and f"{bad}:3:" in err
    assert not (tmp_path / "s_frames").exists() and not (tmp_path / "s.mp4").exists()


def test_no_wood_frames_are_render_no_wood_frames(tmp_path: Path) -> None:
    """--no-wood (constant-shaded surround, as the Sigma draws it) reaches every frame: the
    film's frames are `snooker render --no-wood`'s over the film's own view file."""
    out = tmp_path / "shot.gif"
    args = ["snooker", "film", str(BREAK), str(SCRIPT), "--out", str(out), "--size", "48x32",
            "--workers", "1"]
    assert main([*args, "--no-wood"]) == 0
    plain = tmp_path / "plain"
    assert main(["snooker", "render", str(BREAK), str(tmp_path / "shot.views"), "--frames",
                 str(plain), "--mode", "truecolour", "--size", "48x32", "--no-wood",
                 "--first", "1", "--last", "3", "--workers", "1"]) == 0
    for k in (1, 2, 3):
        name = f"frame_0000{k}.png"
        assert (plain / name).read_bytes() == (tmp_path / "shot_frames" / name).read_bytes()
    wood = tmp_path / "wood"
    assert main(["snooker", "render", str(BREAK), str(tmp_path / "shot.views"), "--frames",
                 str(wood), "--mode", "truecolour", "--size", "48x32", "--first", "1",
                 "--last", "1", "--workers", "1"]) == 0
    assert (wood / "frame_00001.png").read_bytes() != (plain / "frame_00001.png").read_bytes()
