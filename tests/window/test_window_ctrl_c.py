"""``python -m camlab88.emulator.window``: Ctrl-C quits like Escape, status 130, no traceback."""

from __future__ import annotations

import pytest

from camlab88.emulator import window as window_module


def test_ctrl_c_in_the_test_card_quits_cleanly(monkeypatch, capsys) -> None:
    monkeypatch.setattr("camlab88.emulator.harness.display.display_available", lambda: True)

    def interrupted(self):
        raise KeyboardInterrupt

    monkeypatch.setattr(window_module.Window, "poll", interrupted)
    assert window_module.run_module([]) == 130
    assert "interrupted" in capsys.readouterr().err


def test_main_itself_still_raises_for_its_callers(monkeypatch) -> None:
    monkeypatch.setattr("camlab88.emulator.harness.display.display_available", lambda: True)
    monkeypatch.setattr(window_module.Window, "poll",
                        lambda self: (_ for _ in ()).throw(KeyboardInterrupt))
    with pytest.raises(KeyboardInterrupt):
        window_module.main([])
