"""``snooker render --mode truecolour`` through apps.snooker.film's scheduler:
frames from 2 local workers and from ``--dask local`` are byte-identical to the sequential
renderer's, a rerun skips complete frames and re-renders a torn one, films are written;
the Sigma modes in parallel (a fresh T5688 a frame) equal one terminal frame after frame."""

from __future__ import annotations

from pathlib import Path

import imageio.v2 as iio2
import imageio.v3 as iio
import pytest

from camlab88.apps.snooker.render.scene import load_scene
from camlab88.apps.snooker.render.sequence import render_sequence, select_views
from camlab88.base.png import frame_path, png_bytes
from camlab88.cli import main
from camlab88.commands.snooker.render import RECORD
from tests.snooker_render.helpers import BREAK, VIEWS, break_views

FIRST, LAST = 5, 8
ARGS = ["snooker", "render", str(BREAK), str(VIEWS), "--mode", "truecolour",
        "--size", "96x64", "--first", str(FIRST), "--last", str(LAST)]


@pytest.fixture(scope="module")
def sequential() -> dict[int, bytes]:
    """The renderer's own frame-after-frame sequence, encoded as the commands encode it."""
    scene = load_scene(BREAK)
    views = select_views(break_views(), scene, FIRST, LAST, str(VIEWS))
    return {f.frame: png_bytes(f.image)
            for f in render_sequence(scene, views, "truecolour", (96, 64))}


def frames(out: Path) -> dict[int, bytes]:
    return {int(p.stem[6:]): p.read_bytes() for p in sorted(out.glob("frame_*.png"))}


def test_two_local_workers_equal_sequential(tmp_path: Path,
                                            sequential: dict[int, bytes]) -> None:
    assert main([*ARGS, "--frames", str(tmp_path), "--workers", "2"]) == 0
    assert frames(tmp_path) == sequential
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".")) == [RECORD]


def test_dask_local_equals_sequential(tmp_path: Path, sequential: dict[int, bytes]) -> None:
    assert main([*ARGS, "--frames", str(tmp_path), "--dask", "local", "--workers", "2"]) == 0
    assert frames(tmp_path) == sequential


def test_resume_skips_complete_frames_and_redoes_a_torn_one(
        tmp_path: Path, sequential: dict[int, bytes],
        capsys: pytest.CaptureFixture[str]) -> None:
    assert main([*ARGS, "--frames", str(tmp_path), "--workers", "1"]) == 0
    capsys.readouterr()
    torn = frame_path(tmp_path, 6)
    torn.write_bytes(sequential[6][: len(sequential[6]) // 2])
    kept = {f: frame_path(tmp_path, f).stat().st_mtime_ns for f in (5, 7, 8)}
    assert main([*ARGS, "--frames", str(tmp_path), "--workers", "1"]) == 0
    assert "1 rendered, 3 already there" in capsys.readouterr().err
    assert frames(tmp_path) == sequential
    assert {f: frame_path(tmp_path, f).stat().st_mtime_ns for f in kept} == kept


def test_other_settings_are_not_taken_for_done(tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    assert main([*ARGS, "--frames", str(tmp_path), "--workers", "1"]) == 0
    capsys.readouterr()
    assert main([*ARGS, "--frames", str(tmp_path), "--workers", "1", "--no-wood"]) == 0
    assert "4 rendered, 0 already there" in capsys.readouterr().err


def test_gif_and_mp4_are_written(tmp_path: Path, sequential: dict[int, bytes]) -> None:
    gif, mp4 = tmp_path / "shot.gif", tmp_path / "shot.mp4"
    assert main([*ARGS, "--frames", str(tmp_path / "f"), "--workers", "1",
                 "--gif", str(gif), "--mp4", str(mp4)]) == 0
    assert iio.imread(gif).shape == (len(sequential), 64, 96, 3)
    meta = iio.immeta(mp4)
    assert round(meta["fps"]) == 25 and "audio_codec" not in meta
    with iio2.get_reader(mp4, format="FFMPEG") as r:
        assert r.count_frames() == len(sequential)


def test_sigma_modes_refuse_a_size(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    assert main(["snooker", "render", str(BREAK), str(VIEWS), "--frames", str(tmp_path),
                 "--workers", "2", "--size", "96x64"]) == 2
    assert "768x512" in capsys.readouterr().err


def test_period_frames_in_parallel_equal_one_terminal(tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str]
                                                      ) -> None:
    """A fresh T5688 a frame (2 workers) draws exactly what one terminal drawing frame
    after frame draws; the sequential run's record lets a parallel rerun skip its frames."""
    period = ["snooker", "render", str(BREAK), str(VIEWS), "--first", "3", "--last", "4"]
    one, two = tmp_path / "one", tmp_path / "two"
    assert main([*period, "--frames", str(one)]) == 0
    assert "line time" in capsys.readouterr().err
    assert main([*period, "--frames", str(two), "--workers", "2"]) == 0
    assert "2 rendered (a fresh T5688 each)" in capsys.readouterr().err
    assert frames(two) == frames(one) and len(frames(one)) == 2
    assert main([*period, "--frames", str(one), "--workers", "2"]) == 0
    assert "0 rendered (a fresh T5688 each), 2 already there" in capsys.readouterr().err
    assert main([*period, "--frames", str(one), "--workers", "2", "--mode", "fixed"]) == 0
    assert "2 rendered" in capsys.readouterr().err
