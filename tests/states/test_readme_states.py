"""README's "Save states and seeking" section: its commands run as printed, the state is
written and loaded, and the seek passes its check."""

from __future__ import annotations

from pathlib import Path

from camlab88.cli import main
from tests.support.readme import section_commands

ROOT = Path(__file__).resolve().parents[2]


def _commands() -> list[list[str]]:
    return section_commands("Save states and seeking")


def test_the_save_state_commands_run_as_printed(tmp_path: Path, monkeypatch, capsys) -> None:
    commands = _commands()
    assert [c[1] for c in commands] == ["rainbow", "rainbow", "replay"]
    assert "--save-state" in commands[0] and "--load-state" in commands[1]
    assert "--seek" in commands[2]
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    monkeypatch.chdir(tmp_path)
    for words in commands:
        assert main(words[1:]) == 0, (words, capsys.readouterr())
    assert (tmp_path / "pads.c88state").is_file()
    assert (tmp_path / "pads_end.png").is_file()
