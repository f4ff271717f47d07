"""The emulator's control keys on `rainbow replay` (a stream recording) and `tablet emulate`,
in a window on SDL's dummy driver with real pygame key events posted: F5 pauses (the window
is polled while no frame advances), F6 advances exactly one frame, F8 doubles the speed, F5
resumes, F12 saves a screenshot; each command's --help lists the keys."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from camlab88.cli import main

PLAN = {5: "F5", 10: "F6", 15: "F8", 20: "F5", 25: "F12"}  # poll number -> key pressed


@pytest.fixture
def keyed_window(monkeypatch):
    """Window.poll posts PLAN's keys as pygame events before polling; the captions shown
    are kept."""
    import pygame

    from camlab88.emulator import window

    real_poll, real_caption = window.Window.poll, window.Window.set_caption
    seen = {"polls": 0, "captions": []}

    def poll(self):
        seen["polls"] += 1
        name = PLAN.get(seen["polls"])
        if name is not None:
            pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=getattr(pygame, f"K_{name}"),
                                                 unicode="", mod=0))
        return real_poll(self)

    def set_caption(self, text: str) -> None:
        seen["captions"].append(text)
        real_caption(self, text)

    monkeypatch.setattr(window.Window, "poll", poll)
    monkeypatch.setattr(window.Window, "set_caption", set_caption)
    return seen


def _check_the_keys_acted(seen: dict, shots: Path, doubled: str) -> None:
    paused = {int(m.group(1)) for c in seen["captions"] if "PAUSED" in c
              for m in [re.search(r"frame (\d+)", c)] if m}
    assert len(paused) == 2 and max(paused) == min(paused) + 1  # F6: exactly one frame
    last_paused = max(i for i, c in enumerate(seen["captions"]) if "PAUSED" in c)
    after = seen["captions"][last_paused + 1:]  # F8 doubled the speed, then F5 resumed
    shown = [c for c in after if "F1 keys" in c]  # the controls' captions (the others are
    assert shown[0].endswith(f"| {doubled} | speed {doubled} | F1 keys")  # the harness's)
    assert len(list(shots.glob("camlab88-*.png"))) == 1  # F12


def test_rainbow_replay_pauses_steps_speeds_up_and_still_checks(tmp_path: Path, monkeypatch,
                                                                 keyed_window, capsys) -> None:
    rec = tmp_path / "r.rec"
    assert main(["rainbow", "run", "--headless", "--stop-after", "40",
                 "--record-stream", str(rec)]) == 0
    monkeypatch.chdir(tmp_path)
    capsys.readouterr()
    assert main(["rainbow", "replay", str(rec), "--speed", "4"]) == 0
    assert "40 frames, 0 mismatches" in capsys.readouterr().out
    _check_the_keys_acted(keyed_window, tmp_path, "x8")  # --speed 4, doubled
    assert keyed_window["polls"] > 40 + 3  # polled while paused, with no frame advancing


def test_rainbow_replay_stopped_by_escape_is_not_a_pass(tmp_path: Path, monkeypatch,
                                                        capsys) -> None:
    import pygame

    from camlab88.emulator import window

    rec = tmp_path / "r.rec"
    assert main(["rainbow", "run", "--headless", "--stop-after", "40",
                 "--record-stream", str(rec)]) == 0
    real = window.Window.poll

    def poll(self):
        pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_ESCAPE,
                                             unicode="\x1b", mod=0))
        return real(self)

    monkeypatch.setattr(window.Window, "poll", poll)
    capsys.readouterr()
    assert main(["rainbow", "replay", str(rec)]) == 1
    assert "before the end of the recording" in capsys.readouterr().err


def test_tablet_emulate_pauses_steps_and_speeds_up(tmp_path: Path, monkeypatch,
                                                   keyed_window) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["tablet", "emulate", "--demo", "--seconds", "2"]) == 0
    _check_the_keys_acted(keyed_window, tmp_path, "x2")  # period speed, doubled


@pytest.mark.parametrize("command", [["rainbow", "replay"], ["tablet", "emulate"]])
def test_the_help_lists_the_control_keys(command: list[str], capsys) -> None:
    with pytest.raises(SystemExit):
        main([*command, "--help"])
    text = " ".join(capsys.readouterr().out.split())
    for key in ("F1", "F5 pause", "F6 one frame", "F7 / F8", "F12"):
        assert key in text, key
