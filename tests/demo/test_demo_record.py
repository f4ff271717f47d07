"""`camlab88 demo --record FILE`: the whole demo, every act on its own device, is one session
recording (the acts play in one harness run), and `camlab88 replay FILE --check` plays it
again with every screen hash compared; a changed hash or a key the recording holds changes
the verdict."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.protocols.session import read, write


def _record(tmp_path: Path, *extra: str) -> Path:
    rec = tmp_path / "demo.session"
    assert main(["demo", "--only", "sigma", "--only", "shelf", "--out", str(tmp_path / "out"),
                 "--record", str(rec), *extra]) == 0
    return rec


def test_a_headless_demo_recording_replays_with_every_hash_agreeing(tmp_path: Path,
                                                                   capsys) -> None:
    rec = _record(tmp_path, "--headless")
    got = read(rec)
    assert got.argv[:1] == ["demo"] and "--record" not in got.argv
    assert len(got.hashes) >= 28  # 185 Sigma frames and 100 shelf frames, one hash in 10
    capsys.readouterr()
    assert main(["replay", str(rec), "--check"]) == 0
    assert "all 29 screen hashes agree" in capsys.readouterr().out


def test_a_changed_hash_in_a_demo_recording_fails_the_check(tmp_path: Path, capsys) -> None:
    rec = _record(tmp_path, "--headless")
    got = read(rec)
    last = got.hashes[-1]  # a hash in the second act, the shelf on the Rainbow
    got.hashes[-1] = type(last)(last.frame, last.tick, last.time, "0" * 64)
    write(rec, got)
    capsys.readouterr()
    assert main(["replay", str(rec), "--check"]) == 1
    assert f"frame {last.frame}" in capsys.readouterr().err


def test_a_windowed_demo_records_its_space_key_and_replays_it(tmp_path: Path,
                                                              monkeypatch, capsys) -> None:
    """In a window (SDL's dummy driver) Space ends the Sigma act early: the key is in the
    recording at its tick, and the replay ends the act at the same frame."""
    import pygame

    from camlab88.emulator import window

    real, polls = window.Window.poll, []

    def poll(self):
        polls.append(1)
        if len(polls) == 40:  # Space part-way through the first act
            pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_SPACE,
                                                 unicode=" ", mod=0))
        return real(self)

    monkeypatch.setattr(window.Window, "poll", poll)
    rec = _record(tmp_path, "--fast", "--screenshot", str(tmp_path / "end.png"))
    got = read(rec)
    assert not got.headless
    assert [e for _tick, _t, e in got.events if "space" in str(e)]
    assert got.end is not None and got.end.frame < 185 + 100  # the first act cut short
    monkeypatch.setattr(window.Window, "poll", real)
    capsys.readouterr()
    assert main(["replay", str(rec), "--check", "--headless"]) == 0
    assert "screen hashes agree" in capsys.readouterr().out


@pytest.mark.slow
def test_the_whole_demo_is_one_recording_that_replays(tmp_path: Path, capsys) -> None:
    rec = tmp_path / "demo.session"
    assert main(["demo", "--headless", "--out", str(tmp_path / "out"),
                 "--record", str(rec)]) == 0
    capsys.readouterr()
    assert main(["replay", str(rec), "--check"]) == 0
    assert "screen hashes agree" in capsys.readouterr().out
