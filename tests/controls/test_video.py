"""--video: the frames shown, at the program's frame rate, as an MP4 or GIF that
imageio-ffmpeg's ffmpeg reads back with the right frame count."""

from __future__ import annotations

import subprocess
import sys

import pytest

from tests.controls.fakes import FakeClock, harness_with
from tests.support.targets import Counter

imageio_ffmpeg = pytest.importorskip("imageio_ffmpeg", reason="--video needs imageio-ffmpeg")


@pytest.mark.parametrize("name", ["run.mp4", "run.gif"])
def test_video_has_one_frame_per_frame_shown_at_the_programs_rate(tmp_path, name) -> None:
    out = tmp_path / name
    h = harness_with(Counter(60, size=(64, 48)), None, FakeClock(), video=out).run()
    frames, secs = imageio_ffmpeg.count_frames_and_secs(str(out))
    # frames at ticks 1, 3 ... 59 and the last picture at tick 60
    assert h.frames_shown == 31 and frames == 31
    assert secs == pytest.approx(31 / 25, abs=0.05)
    assert [p.name for p in tmp_path.iterdir()] == [name]  # no temporary left


def test_a_frame_that_stood_longer_is_repeated_so_the_video_keeps_time(tmp_path) -> None:
    class Slow(Counter):
        def tick(self) -> bool:  # virtual time jumps three frame periods every tick
            self.t += 6
            return self.t < 60

    out = tmp_path / "slow.mp4"
    h = harness_with(Slow(60, size=(64, 48)), None, FakeClock(), video=out).run()
    frames, _ = imageio_ffmpeg.count_frames_and_secs(str(out))
    assert h.frames_shown == 10 and frames == 1 + 9 * 3


def test_video_flag_on_a_device_program(tmp_path) -> None:
    out = tmp_path / "demo.mp4"
    run = subprocess.run(
        [sys.executable, "-m", "camlab88", "rainbow", "run", "--demo", "pads", "--headless",
         "--stop-after", "12", "--video", str(out)],
        capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert f"video {out} (12 frames at 50 fps)" in run.stderr
    assert imageio_ffmpeg.count_frames_and_secs(str(out))[0] == 12


def test_a_video_that_is_not_mp4_or_gif_is_refused_in_one_line(tmp_path) -> None:
    run = subprocess.run(
        [sys.executable, "-m", "camlab88", "rainbow", "run", "--demo", "pads", "--headless",
         "--video", str(tmp_path / "x.avi")], capture_output=True, text=True, timeout=120)
    assert run.returncode == 2
    assert "--video: makes .mp4 or .gif, not" in run.stderr


def test_an_inspect_out_that_is_a_file_is_refused_in_one_line(tmp_path, capsys) -> None:
    from camlab88.cli import main

    (tmp_path / "s.sig").write_bytes(b"\r+-*/HI2GI200200GJ600200")
    (tmp_path / "taken").write_text("a file")
    try:
        status = main(["sigma", "render", "--in", str(tmp_path / "s.sig"), "--inspect-out",
                       str(tmp_path / "taken")])
    except SystemExit as exc:
        status, message = 2, str(exc.code)
    else:
        message = capsys.readouterr().err
    assert status == 2  # docs/exit_status.md: an output that cannot be written, before the work
    assert f"{tmp_path / 'taken'}: it is a file in the way, not a directory" in message
    assert len(message.strip().splitlines()) == 1
    assert (tmp_path / "taken").read_text() == "a file"
