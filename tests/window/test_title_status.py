"""The visualiser's and KAS paint's windows name their keys, the frame shown and the
(virtual or line) time in the title bar, like the other programs show theirs on screen."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.apps.kas import files
from camlab88.cli import main
from tests.kas_paint.helpers import walk

DATA = Path(__file__).resolve().parents[1] / "data"


@pytest.fixture()
def captions(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    from camlab88.emulator import window

    seen: list[str] = []
    real = window.Window.set_caption

    def spy(self, text: str) -> None:
        seen.append(text)
        real(self, text)
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    monkeypatch.setattr(window.Window, "set_caption", spy)
    return seen


def test_the_visualiser_window_shows_frame_time_and_keys(captions: list[str]) -> None:
    d = DATA / "snooker_render"
    assert main(["snooker", "visualise", str(d / "break.checkpoint"), str(d / "break.views"),
                 "--stop-after", "3"]) == 0
    assert captions, "the title bar was never set"
    last = captions[-1]
    assert last.startswith("camlab88 snooker visualise | frame ") and " of " in last
    assert "t = " in last and "space play/pause" in last


def test_the_kas_paint_windows_show_frame_line_time_and_keys(tmp_path: Path,
                                                             captions: list[str]) -> None:
    seq, ops = tmp_path / "w.kas", tmp_path / "w.ops"
    files.save_sequence(seq, walk(3))
    ops.write_text("KAS paint 1\npalette 1\ncolour 0 0 0 0\ngap 0\npainted 1\nops 0\nend\n")
    assert main(["kas", "paint", str(seq), "--ops", str(ops), "--replay",
                 "--stop-after", "2"]) == 0
    assert "frame 2 of 3, line time " in captions[-1] and "close the window" in captions[-1]
    captions.clear()
    assert main(["kas", "paint", str(seq), "--stop-after", "2"]) == 0
    assert "frame 2 of 3, line time 0.0" in captions[0] and "f fill" in captions[0]
