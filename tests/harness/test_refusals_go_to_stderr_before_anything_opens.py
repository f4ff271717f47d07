"""Refusals go to stderr, and come before anything is opened or announced
(docs/newcomer_trial.md lists where each was found)."""

from __future__ import annotations

import pytest

from camlab88.emulator.harness.display import DisplayRefused


def _no_display(monkeypatch: pytest.MonkeyPatch) -> None:
    for var in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(var, raising=False)
    monkeypatch.setattr("sys.platform", "linux")


def test_the_window_test_card_refuses_on_stderr(monkeypatch: pytest.MonkeyPatch,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    from camlab88.emulator import window

    _no_display(monkeypatch)
    assert window.main([]) == 2
    out, err = capsys.readouterr()
    assert out == "" and "no display for a window" in err


def test_a_mouse_driven_emulated_tablet_refuses_before_opening_its_pty(
        monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    from camlab88.cli import main
    from camlab88.emulator.tablet_input import emulated_source

    _no_display(monkeypatch)
    opened = []
    monkeypatch.setattr(emulated_source, "EmulatedSource",
                        lambda *a, **k: opened.append(a) or pytest.fail("pty opened"))
    with pytest.raises((SystemExit, DisplayRefused), match="no display for a window"):
        main(["tablet", "monitor", "emulated:summa-mm"])
    assert opened == [] and "pty" not in capsys.readouterr().out


def test_an_os_error_reads_file_then_reason(capsys: pytest.CaptureFixture[str]) -> None:
    from camlab88.runopts import fail

    try:
        open("/nonexistent/x.kas", encoding="utf-8")
    except OSError as exc:
        assert fail("camlab88 kas", exc) == 2
    err = capsys.readouterr().err
    assert err == "camlab88 kas: /nonexistent/x.kas: No such file or directory\n"
