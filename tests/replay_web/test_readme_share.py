"""README's "Share a session" section, exactly as printed: record, the page as one file and
as a directory, and a one-figure gallery."""

from __future__ import annotations

from pathlib import Path

from tests.replay_web.helpers import page_data
from tests.support.readme import run_as_printed, section_commands


def test_the_share_commands_run_as_printed(tmp_path: Path, monkeypatch) -> None:
    commands = section_commands("Share a session")
    assert [c[1] for c in commands] == ["ca", "replay", "replay", "figures"]
    run_as_printed(commands, tmp_path, monkeypatch)
    assert len(page_data(tmp_path / "share.html")["frames"]) > 10
    assert sorted(p.name for p in (tmp_path / "share_site").iterdir()) == ["index.html",
                                                                            "session.mp4"]
    assert (tmp_path / "gallery" / "fig-6.5.html").is_file()
    assert (tmp_path / "gallery" / "index.html").is_file()
