"""README's "Save states and seeking" section: its commands run as printed, the state is
written and loaded, and the seek passes its check."""

from __future__ import annotations

from pathlib import Path

from tests.support.readme import run_as_printed, section_commands


def test_the_save_state_commands_run_as_printed(tmp_path: Path, monkeypatch) -> None:
    commands = section_commands("Save states and seeking")
    assert [c[1] for c in commands] == ["rainbow", "rainbow", "replay"]
    assert "--save-state" in commands[0] and "--load-state" in commands[1]
    assert "--seek" in commands[2]
    run_as_printed(commands, tmp_path, monkeypatch)
    assert (tmp_path / "pads.c88state").is_file()
    assert (tmp_path / "pads_end.png").is_file()
