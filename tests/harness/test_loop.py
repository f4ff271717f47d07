"""The harness loop: tick order and plugins, stopping, the display rule, --frames DIR."""

from __future__ import annotations

import argparse

import numpy as np
import pytest

from camlab88.emulator.harness import DisplayRefused, Plugin, RunOptions, choose_headless, run
from camlab88.emulator.host_input import KeyDown, Quit
from tests.support.targets import Counter


class Log(Plugin):
    def __init__(self, inject: dict[int, list] | None = None) -> None:
        self.calls: list[tuple[str, int]] = []
        self.inject = inject or {}

    def start(self, harness) -> None:
        self.calls.append(("start", harness.ticks))

    def handle_events(self, harness, events):
        return events + self.inject.get(harness.ticks, [])

    def on_frame(self, harness, frame) -> None:
        self.calls.append(("frame", int(frame[0, 0, 0])))

    def finish(self, harness) -> None:
        self.calls.append(("finish", harness.ticks))


def test_frames_are_shown_every_1_over_fps_and_the_last_one_at_the_end() -> None:
    log = Log()
    h = run(Counter(7), RunOptions(), [log])
    assert h.ticks == 7
    assert log.calls == [("start", 0), ("frame", 1), ("frame", 3), ("frame", 5),
                         ("frame", 7), ("finish", 7)]


def test_stop_after_counts_frames_and_events_reach_the_target() -> None:
    log = Log({2: [KeyDown("a", "a")]})
    target = Counter(100)
    h = run(target, RunOptions(stop_after=3), [log])
    assert h.frames_shown == 3 and target.got == [KeyDown("a", "a")]


def test_quit_stops_unless_the_target_refuses() -> None:
    h = run(Counter(100), RunOptions(), [Log({4: [Quit()]})])
    assert h.quit and h.ticks == 4
    h = run(Counter(10, closable=False), RunOptions(), [Log({4: [Quit()]})])
    assert not h.quit and h.ticks == 10


def test_frames_dir_and_screenshot(tmp_path) -> None:
    from PIL import Image

    run(Counter(6), RunOptions(frames=tmp_path / "f", screenshot=tmp_path / "s.png"))
    names = sorted(p.name for p in (tmp_path / "f").iterdir())
    assert names == [f"frame_{k:05d}.png" for k in range(4)]  # t = 1, 3, 5 and the end, 6
    assert np.asarray(Image.open(tmp_path / "s.png"))[0, 0, 0] == 6


def test_an_unwritable_screenshot_is_one_line_naming_it() -> None:
    with pytest.raises(SystemExit, match="cannot write /proc/nope/s.png"):
        run(Counter(2), RunOptions(screenshot="/proc/nope/s.png", command="x"))


def test_the_display_rule(monkeypatch, capsys) -> None:
    for var in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(var, raising=False)
    monkeypatch.setattr("sys.platform", "linux")
    assert choose_headless("cmd", True, None) is True
    assert choose_headless("cmd", False, "writing frames") is True
    assert "cmd: no display; running headless (writing frames)" in capsys.readouterr().err
    with pytest.raises(DisplayRefused, match="cmd: no display for a window; give --events"):
        choose_headless("cmd", False, None, "give --events")
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    assert choose_headless("cmd", False, None) is False


def test_interactive_commands_without_display_refuse_in_one_line(monkeypatch) -> None:
    from camlab88.cli import main

    for var in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(var, raising=False)
    for argv in (["snooker", "play"], ["ca", "program"]):
        with pytest.raises(SystemExit) as exc:
            main(argv)
        assert "no display for a window; give --headless with --events FILE" in str(
            exc.value.code)


def test_frames_takes_a_directory_and_refuses_a_count() -> None:
    from camlab88.runopts import frames_dir

    with pytest.raises(argparse.ArgumentTypeError, match="use --stop-after 30"):
        frames_dir("30")
    assert str(frames_dir("out")) == "out"
