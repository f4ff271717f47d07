"""`camlab88 ca film`: rules + pattern + actors -> frames -> GIF/MP4, resumable; bad input
refused in one line before anything is rendered."""

from __future__ import annotations

from pathlib import Path

import imageio.v3 as iio
import pytest

from camlab88.cli import main
from tests.cafilm.helpers import CHESS, ROOT

GUN_CCL = str(ROOT / "examples" / "ca" / "gun.ccl")


def _args(tmp_path: Path, *extra: str) -> list[str]:
    return ["ca", "film", "life", "glider", "--actors", CHESS, "--generations", "2",
            "--frames-per-generation", "2", "--size", "48x32", "--workers", "1",
            "--out", str(tmp_path / "g.gif"), *extra]


def test_a_film_in_one_command_and_a_second_run_renders_nothing(tmp_path: Path,
                                                                capsys) -> None:
    args = _args(tmp_path, "--gif", str(tmp_path / "also.gif"))
    args[args.index("--out") + 1] = str(tmp_path / "g.mp4")
    assert main(args) == 0
    frames = sorted((tmp_path / "g_frames").glob("frame_*.png"))
    assert len(frames) == 5  # 2 generations x 2 frames, and generation 0
    assert iio.imread(tmp_path / "also.gif").shape == (5, 32, 48, 3)
    assert (tmp_path / "g.mp4").read_bytes()[4:8] == b"ftyp"  # an MP4 container
    assert "5 rendered, 0 already there" in capsys.readouterr().err
    assert main(args) == 0
    assert "0 rendered, 5 already there" in capsys.readouterr().err


def test_the_camera_script_counts_generations(tmp_path: Path, capsys) -> None:
    assert main(_args(tmp_path, "--camera", GUN_CCL)) == 0
    bad = tmp_path / "late.ccl"
    bad.write_text("x: FROM 1 UNTIL 3; VIEWPOINT AT (0, 0, 0)\n")
    capsys.readouterr()
    assert main(_args(tmp_path, "--camera", str(bad))) == 2
    err = capsys.readouterr().err
    assert f"{bad}:1:17: this command would run until frame 3, after the last frame (2)" \
        in err
    assert "nothing rendered" in err


def test_a_bad_actors_file_is_one_line_naming_where(tmp_path: Path, capsys) -> None:
    bad = tmp_path / "bad.actors"
    bad.write_text("rules life\nactor 1 pawn\n  colour 1 2\nend\n")
    args = _args(tmp_path)
    args[args.index("--actors") + 1] = str(bad)
    assert main(args) == 2
    err = capsys.readouterr().err
    assert err == f"camlab88 ca film: {bad}:3:13: expected blue, the line ends\n"
    assert not (tmp_path / "g_frames").exists()


@pytest.mark.parametrize(("extra", "words"), [
    (("--mode", "t5688", "--dask", "local"), "--size, --dask and --workers are truecolour's"),
    (("--glide", "2,x"), "--glide: expected all, none or states"),
    (("--camera", "nope.ccl"), "nope.ccl: no such file"),
    (("--samples", "9"), "--samples must be 1..4"),
    (("--size", "8192x8192"), "samples a frame: a smaller --size or fewer --samples"),
    (("--seed", "99999999999999999999"), "--seed: 99999999999999999999 is outside"),
])
def test_bad_options_are_refused_before_any_work(tmp_path: Path, capsys, extra: tuple[str, ...],
                                                 words: str) -> None:
    args = [a for a in _args(tmp_path) if a not in ("--size", "48x32", "--workers", "1")]
    assert main(args + list(extra)) == 2
    assert words in capsys.readouterr().err


def test_an_unknown_pattern_names_the_library(tmp_path: Path, capsys) -> None:
    args = _args(tmp_path)
    args[3] = "glidr"
    assert main(args) == 2
    assert "no pattern file or library entry named 'glidr'" in capsys.readouterr().err
