"""Resuming: complete frames of the same scene, view and look are skipped; a missing, torn,
foreign or stale frame is rendered again; a failing frame is retried and reported, and a
frame that keeps failing leaves no file behind."""

from __future__ import annotations

from concurrent.futures import Future
from dataclasses import replace
from pathlib import Path

import pytest

from camlab88.apps.snooker.film.backends import InProcess
from camlab88.apps.snooker.film.pngcheck import is_complete
from camlab88.apps.snooker.film.schedule import FilmError, frame_file, render_film
from camlab88.apps.snooker.film.task import FrameTask, scene_digest
from camlab88.base.png import png_bytes
from tests.snooker_film.helpers import SIZE, break_scene, frame_bytes, small_tasks


def _film(tasks: list[FrameTask], out: Path, backend: object = None):
    scene = break_scene()
    return render_film(tasks, out, backend or InProcess(scene), scene_digest(scene))


def test_resuming_skips_finished_frames_and_redoes_broken_ones(
        reference: dict[int, bytes], tmp_path: Path) -> None:
    tasks = small_tasks()
    assert sorted(_film(tasks, tmp_path).rendered) == list(range(1, 9))
    again = _film(tasks, tmp_path)
    assert again.rendered == [] and sorted(again.skipped) == list(range(1, 9))
    frame_file(tmp_path, 2).unlink()
    torn = frame_file(tmp_path, 3)
    torn.write_bytes(torn.read_bytes()[:-40])  # a PNG cut short
    import numpy as np

    frame_file(tmp_path, 5).write_bytes(png_bytes(np.zeros((SIZE[1] * 2, SIZE[0], 3),
                                                            dtype=np.uint8)))  # wrong size
    report = _film(tasks, tmp_path)
    assert sorted(report.rendered) == [2, 3, 5]
    assert frame_bytes(tmp_path, tasks) == reference


def test_a_changed_look_renders_every_frame_again(tmp_path: Path) -> None:
    tasks = small_tasks(range(1, 4))
    _film(tasks, tmp_path)
    no_specks = [replace(t, specks=False) for t in tasks]
    assert sorted(_film(no_specks, tmp_path).rendered) == [1, 2, 3]


def test_complete_means_decodes_whole_at_the_size(tmp_path: Path) -> None:
    f = tmp_path / "f.png"
    assert not is_complete(f, SIZE)
    f.write_bytes(b"\x89PNG\r\n\x1a\n not really")
    assert not is_complete(f, SIZE)


class Flaky(InProcess):
    """Fails the first ``n`` attempts of every frame in ``frames``."""

    def __init__(self, frames: set[int], n: int) -> None:
        super().__init__(break_scene())
        self.frames, self.n, self.seen = frames, n, {}

    def submit(self, task: FrameTask) -> Future:
        k = self.seen[task.frame] = self.seen.get(task.frame, 0) + 1
        if task.frame in self.frames and k <= self.n:
            f: Future = Future()
            f.set_exception(RuntimeError(f"worker lost frame {task.frame}"))
            return f
        return super().submit(task)


def test_a_failed_frame_is_retried_and_reported(reference: dict[int, bytes],
                                                tmp_path: Path) -> None:
    tasks = small_tasks()
    report = _film(tasks, tmp_path, Flaky({4}, 2))
    assert report.retries == [(4, "RuntimeError: worker lost frame 4")] * 2
    assert frame_bytes(tmp_path, tasks) == reference


def test_a_frame_that_keeps_failing_is_named_and_leaves_no_file(tmp_path: Path) -> None:
    tasks = small_tasks(range(1, 4))
    with pytest.raises(FilmError, match="frames 2 failed after 3 attempts"):
        _film(tasks, tmp_path, Flaky({2}, 3))
    assert not frame_file(tmp_path, 2).exists()
    assert frame_file(tmp_path, 1).exists() and frame_file(tmp_path, 3).exists()
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


def test_resume_checks_each_frame_against_the_hash_of_what_was_written(
        reference: dict[int, bytes], tmp_path: Path) -> None:
    """A valid PNG of the right size is not enough: a frame copied over another, or one
    with 20 pixels repainted, is not what the manifest says was written: made again."""
    import imageio.v3 as iio

    from camlab88.apps.snooker.film.pngcheck import png_size

    tasks = small_tasks()
    _film(tasks, tmp_path)
    frame_file(tmp_path, 4).write_bytes(frame_file(tmp_path, 6).read_bytes())  # copied over
    image = iio.imread(frame_file(tmp_path, 7).read_bytes()).copy()
    image[10, 10:30] = 255 - image[10, 10:30]  # 20 pixels repainted
    frame_file(tmp_path, 7).write_bytes(png_bytes(image))
    assert png_size(frame_file(tmp_path, 7).read_bytes()) == SIZE
    report = _film(tasks, tmp_path)
    assert sorted(report.rendered) == [4, 7]
    assert frame_bytes(tmp_path, tasks) == reference
