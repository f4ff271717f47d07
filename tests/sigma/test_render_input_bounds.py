"""`sigma render` on damaged input: a recording behind a byte-order mark is refused (it was drawn
as raw bytes, exit 0), and a recording whose last time is 10^8 s is refused before any PNG is
written (it would have meant 2.5 billion frames)."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.protocols.link import LineSettings
from camlab88.protocols.link.recording import MAGIC, Recorder


def _recording(path: Path, last_t: int) -> Path:
    rec = Recorder(path, LineSettings(baud=9600))
    rec.record(0.01, ">", b"\x1b")
    rec.record(last_t, ">", b"\x1b")
    rec.close()
    return path


def test_a_bom_before_a_recording_is_refused_naming_the_file(tmp_path: Path, capsys) -> None:
    good = _recording(tmp_path / "good.rec", 1)
    bom = tmp_path / "bom.rec"
    bom.write_bytes(b"\xef\xbb\xbf" + good.read_bytes())
    with pytest.raises(SystemExit) as exc:
        main(["sigma", "render", "--in", str(bom), "--out", str(tmp_path / "x.png")])
    assert f"{bom}:1:1" in str(exc.value.code) and "byte-order mark" in str(exc.value.code)
    assert not (tmp_path / "x.png").exists()


def test_a_damaged_first_line_is_not_drawn_as_raw_bytes(tmp_path: Path) -> None:
    good = _recording(tmp_path / "good.rec", 1)
    damaged = tmp_path / "damaged.rec"
    damaged.write_bytes(good.read_bytes().replace(MAGIC.encode(), b"camlab88-link-recprding", 1))
    with pytest.raises(SystemExit) as exc:
        main(["sigma", "render", "--in", str(damaged), "--out", str(tmp_path / "x.png")])
    assert str(damaged) in str(exc.value.code)


def test_frames_of_a_recording_lasting_years_are_refused_before_writing(tmp_path: Path) -> None:
    rec = _recording(tmp_path / "long.rec", 10**8)
    out = tmp_path / "frames"
    with pytest.raises(SystemExit) as exc:
        main(["sigma", "render", "--in", str(rec), "--frames", str(out)])
    assert "frames, more than" in str(exc.value.code)
    assert not out.exists() or not list(out.glob("*.png"))


def test_frames_of_a_short_recording_are_written(tmp_path: Path) -> None:
    rec = _recording(tmp_path / "short.rec", 1)
    out = tmp_path / "frames"
    assert main(["sigma", "render", "--in", str(rec), "--frames", str(out)]) == 0
    assert len(list(out.glob("frame_*.png"))) == 25  # one per 1/25 s up to t = 1 s
