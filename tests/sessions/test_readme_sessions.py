"""README's "Sessions" section: record -> replay -> check, exactly as printed."""

from __future__ import annotations

from pathlib import Path

from tests.support.readme import run_as_printed, section_commands


def test_the_three_commands_run_as_printed(tmp_path: Path, monkeypatch, capsys) -> None:
    commands = section_commands("Sessions")
    assert [c[1] for c in commands] == ["ca", "replay", "replay"]
    run_as_printed(commands, tmp_path, monkeypatch)
    out = capsys.readouterr().out
    assert "screen hashes agree" in out
    assert (tmp_path / "glider_frames" / "frame_00000.png").exists()
