"""The progress bar: frames done, frames a second, time left; quiet off a terminal."""

from __future__ import annotations

import io

from camlab88.apps.snooker.film.progress import ProgressBar, progress_bar


def test_the_bar_shows_done_rate_and_time_left() -> None:
    now = [100.0]
    out = io.StringIO()
    bar = ProgressBar("film", out, lambda: now[0])
    bar(10, 250)  # ten frames were already on disk: they do not count towards the rate
    now[0] = 104.0
    bar(30, 250)
    assert out.getvalue().split("\r")[-1] == (
        "film [###...........................] 30/250 5.0 frames/s 44 s left")
    now[0] = 150.0
    bar(250, 250)
    assert out.getvalue().endswith("250/250 4.8 frames/s 0 s left\n")


def test_quiet_when_stderr_is_not_a_terminal(capsys) -> None:
    assert progress_bar("film") is None  # pytest captures stderr: not a terminal
