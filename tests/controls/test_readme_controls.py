"""README's "Emulator controls" section: its commands run as printed and write what it says."""

from __future__ import annotations

from pathlib import Path

from tests.support.readme import run_as_printed, section_commands

ROOT = Path(__file__).resolve().parents[2]


def test_the_controls_commands_run_as_printed(tmp_path: Path, monkeypatch, capsys) -> None:
    import imageio_ffmpeg

    commands = section_commands("Emulator controls")
    assert [c[1] for c in commands] == ["sigma", "rainbow", "ca", "replay", "demo", "replay"]
    run_as_printed(commands, tmp_path, monkeypatch)
    assert "all 11 screen hashes agree" in capsys.readouterr().out  # the demo's recording
    panels = sorted((tmp_path / "cameron_panels").iterdir())
    assert imageio_ffmpeg.count_frames_and_secs("cameron.mp4")[0] == len(panels) > 1
    assert (tmp_path / "scene_panel" / "frame_00000.png").is_file()
    assert imageio_ffmpeg.count_frames_and_secs("glider.gif")[0] > 1
    assert (tmp_path / "glider_panels" / "frame_00000.png").is_file()
    assert "images" in (ROOT / "docs" / "images" / "inspector_sigma.png").parent.name
