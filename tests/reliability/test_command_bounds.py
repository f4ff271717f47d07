"""Bounds the commands apply before any work: a seed the CA kernels
cannot take, a snooker frame rate that would fill memory, a directory given as a session."""

from __future__ import annotations

from pathlib import Path

from camlab88.cli import main


def test_ca_run_refuses_a_seed_past_int64(capsys) -> None:
    assert main(["ca", "run", "--rules", "life", "--pattern", "glider", "--generations", "1",
                 "--seed", "1" * 20]) == 2
    assert "--seed" in capsys.readouterr().err


def test_snooker_table_frame_rate_is_bounded(tmp_path: Path, capsys) -> None:
    code = main(["snooker", "simulate", "--break", "5", "--table", "frame_rate=1000000000",
                 "--out", str(tmp_path / "x.cp")])
    assert code == 2
    assert "frame_rate 1000000000 is outside 1..1000" in capsys.readouterr().err
    assert not (tmp_path / "x.cp").exists()


def test_snooker_play_refuses_a_directory_as_its_session(tmp_path: Path, capsys) -> None:
    code = main(["snooker", "play", "--headless", str(tmp_path), "--stop-after", "1"])
    assert code == 2
    assert "is a directory" in capsys.readouterr().err
