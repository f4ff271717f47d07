"""README's "Sessions" section: record -> replay -> check, exactly as printed."""

from __future__ import annotations

from pathlib import Path

from camlab88.cli import main
from tests.support.readme import section_commands

ROOT = Path(__file__).resolve().parents[2]


def _commands() -> list[list[str]]:
    return section_commands("Sessions")


def test_the_three_commands_run_as_printed(tmp_path: Path, monkeypatch, capsys) -> None:
    commands = _commands()
    assert [c[1] for c in commands] == ["ca", "replay", "replay"]
    (tmp_path / "examples").symlink_to(ROOT / "examples")  # run from "the repository top"
    monkeypatch.chdir(tmp_path)
    for words in commands:
        assert main(words[1:]) == 0, words
    out = capsys.readouterr().out
    assert "screen hashes agree" in out
    assert (tmp_path / "glider_frames" / "frame_00000.png").exists()
