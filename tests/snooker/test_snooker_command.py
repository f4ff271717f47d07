"""`camlab88 snooker simulate`, end to end through the console-script entry point."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.snooker import checkpoint
from camlab88.apps.snooker.checkpoint import to_units
from camlab88.apps.snooker.layout import opening_state
from camlab88.apps.snooker.table import Table
from camlab88.cli import main


def test_break_writes_a_checkpoint_that_starts_from_the_opening_position(tmp_path, capsys):
    out = tmp_path / "break.cp"
    assert main(["snooker", "simulate", "--break", "5", "--out", str(out)]) == 0
    cp = checkpoint.read(out)
    assert np.array_equal(cp.positions[0], to_units(opening_state(Table()).pos))
    assert cp.n_frames > 50
    assert not np.array_equal(cp.positions[-1], cp.positions[0])
    assert "time frames" in capsys.readouterr().out


def test_shot_from_a_session_and_from_a_checkpoint(tmp_path):
    first, sess = tmp_path / "a.cp", tmp_path / "a.json"
    assert main(["snooker", "simulate", "--break", "4", "--out", str(first),
                 "--save-session", str(sess)]) == 0
    second = tmp_path / "b.cp"
    assert main(["snooker", "simulate", "--from", str(sess), "--shot", "cue", "2", "90",
                 "-0.3", "--out", str(second)]) == 0
    a, b = checkpoint.read(first), checkpoint.read(second)
    assert b.n_frames > a.n_frames  # the session continues: earlier frames are kept
    assert np.array_equal(b.positions[: a.n_frames], a.positions)
    third = tmp_path / "c.cp"
    assert main(["snooker", "simulate", "--from", str(second), "--shot", "1", "1.5", "180",
                 "--out", str(third), "--first", "0", "--last", "5"]) == 0
    c = checkpoint.read(third)
    assert c.n_frames == 6 and np.array_equal(c.positions[0], b.positions[-1])


def test_table_constants_on_the_command_line(tmp_path):
    out = tmp_path / "giant.cp"
    assert main(["snooker", "simulate", "--shot", "cue", "3", "0", "--out", str(out),
                 "--table", "cushion_restitution=1.1"]) == 0
    assert checkpoint.read(out).n_frames > 10


@pytest.mark.parametrize(
    "argv,message",
    [
        (["--break", "5", "--from", "x.json"], "cannot be used with --from"),
        (["--shot", "purple", "1", "0"], "unknown ball"),
        (["--shot", "cue", "fast", "0"], "not numbers"),
        (["--shot", "cue", "1"], "BALL SPEED_M_S ANGLE_DEG"),
        (["--break", "5", "--table", "colour=red"], "unknown table constant"),
        (["--break", "5", "--table", "ball_diameter_m=-1"], "ball_diameter_m"),
        (["--shot", "cue", "1", "0", "--from", "MISSING"], "MISSING"),
    ],
)
def test_errors_are_clear(tmp_path, capsys, argv, message):
    code = main(["snooker", "simulate", *argv, "--out", str(tmp_path / "o.cp")])
    assert code == 2
    assert message in capsys.readouterr().err
    assert not (tmp_path / "o.cp").exists()


def test_bad_checkpoint_source_names_the_line(tmp_path, capsys):
    bad = tmp_path / "bad.cp"
    bad.write_text("1,2\n" * 22 + "1 2\n-1\n")
    code = main(["snooker", "simulate", "--from", str(bad), "--shot", "cue", "1", "0",
                 "--out", str(tmp_path / "o.cp")])
    assert code == 2 and f"{bad}:23:" in capsys.readouterr().err


def test_snooker_without_action_is_the_interactive_program(capsys):
    from camlab88.cli import normalise_argv

    assert normalise_argv(["snooker"]) == ["snooker", "play"]
    assert normalise_argv(["snooker", "game.json", "--headless"]) == [
        "snooker", "play", "game.json", "--headless"]
    assert normalise_argv(["snooker", "simulate", "--break", "5"])[1] == "simulate"
    assert normalise_argv(["kas", "library"]) == ["kas", "library"]
    try:
        main(["snooker", "--help"])
    except SystemExit as exc:
        assert exc.code == 0
    assert "simulate" in capsys.readouterr().out


def test_a_table_that_never_settles_stops_with_an_error(tmp_path, capsys):
    code = main(["snooker", "simulate", "--shot", "cue", "5", "80", "--table",
                 "cushion_restitution=1.5", "--max-seconds", "5", "--out", str(tmp_path / "o.cp")])
    assert code == 2 and "still moving after 5" in capsys.readouterr().err
