"""``camlab88 ca program`` headless with scripted input; the demo function."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from PIL import Image

from camlab88.apps.ca.program.demo import choose, demo_events, leave_editing
from camlab88.apps.ca.program.program import CAProgram, Options
from camlab88.apps.ca.program.script_events import parse, play
from camlab88.cli import main
from camlab88.emulator.machine import RainbowMachine


def _json_last(capsys) -> dict:
    return json.loads(capsys.readouterr().out.strip().splitlines()[-1])


def test_program_headless_events_log_and_script(tmp_path: Path, capsys) -> None:
    events = tmp_path / "session.events"
    events.write_text(leave_editing() + "click right 600 500\nframes 1\n" * 5
                      + choose("Zoom 4") + "click right 600 500\nframes 1\n" * 3)
    log_path = tmp_path / "run.log"
    shot = tmp_path / "shot.png"
    assert main(["ca", "program", "--headless", "--pattern", "acorn", "--events", str(events),
                 "--log", str(log_path), "--record-pans", "--checkpoint", "4", "--json"]) == 0
    stats = _json_last(capsys)
    assert stats["generation"] == 8 and stats["viewport"][2] == "4"
    assert (tmp_path / "run.log4").exists() and (tmp_path / "run.log8").exists()
    # a screenshot run of the same session shows the same state and writes no log
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    assert main(["ca", "program", "--headless", "--pattern", "acorn", "--events", str(events),
                 "--log", str(log_path), "--record-pans", "--checkpoint", "4",
                 "--screenshot", str(shot), "--json"]) == 0
    assert _json_last(capsys) == stats
    assert np.asarray(Image.open(shot)).shape == (576, 768, 3)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir() if p != shot} == before
    assert " zoom 4" in log_path.read_text()
    # the log as a Script, begun at generation 8, reaches the same state
    assert main(["ca", "program", "--headless", "--script", str(log_path), "--start", "8",
                 "--replay-pans", "--stop-after", "1", "--json"]) == 0
    again = _json_last(capsys)
    assert again == stats
    assert main(["ca", "replay", "--script", str(log_path), "--generation", "8",
                 "--json"]) == 0
    replayed = _json_last(capsys)
    assert (replayed["population"], replayed["bbox"]) == (stats["population"], stats["bbox"])


def test_program_reports_bad_files(tmp_path: Path, capsys) -> None:
    bad = tmp_path / "bad.events"
    bad.write_text("move 1 2\nwiggle\n")
    assert main(["ca", "program", "--headless", "--events", str(bad)]) == 2
    assert "bad.events:2:1: unknown command 'wiggle'" in capsys.readouterr().err
    assert main(["ca", "program", "--headless", "--rules", "nosuch"]) == 2
    assert "no rules file or library entry named 'nosuch'" in capsys.readouterr().err


def test_demo_plays_sixty_generations_of_the_gun() -> None:
    session = RainbowMachine()
    program = CAProgram(session.client, Options(rules="life", pattern="gosper_gun"))
    play(parse(demo_events(60), "<ca demo>"), session.post, program.frame,
         lambda: program.finished)
    stats = program.session.statistics()
    assert stats["generation"] == 60 and stats["population"] == 46  # the gun and two gliders
    assert stats["viewport"][2] == "8"


def test_tripos_form_does_what_the_flag_form_does(tmp_path: Path, capsys,
                                                 monkeypatch) -> None:
    """Section 7.3.1's argument form: Log/k, RecordPansAndZooms/s, Checkpoint (positional
    too), Script/k, ReplayPansAndZooms/s give the same session as the --flag form."""
    monkeypatch.chdir(tmp_path)
    events = tmp_path / "s.events"
    events.write_text(leave_editing() + "click right 600 500\nframes 1\n" * 4
                      + choose("Zoom 4") + "click right 600 500\nframes 1\n" * 2)
    runs = {}
    for form, words in (("flags", ["--log", "f.log", "--record-pans", "--checkpoint", "3"]),
                        ("tripos", ["Log", "t.log", "RecordPansAndZooms", "3"])):
        assert main(["ca", "program", "--headless", "--pattern", "acorn", "--events",
                     str(events), "--json", *words]) == 0
        runs[form] = _json_last(capsys)
    assert runs["tripos"] == runs["flags"]
    assert " zoom 4" in (tmp_path / "t.log").read_text()  # RecordPansAndZooms took effect
    assert (tmp_path / "t.log3").exists() and (tmp_path / "t.log6").exists()
    assert (tmp_path / "t.log").read_text().replace("t.log", "f.log") \
        == (tmp_path / "f.log").read_text().replace("t.log", "f.log")
    # Script/k with ReplayPansAndZooms/s, in another case and with KEY=value
    assert main(["ca", "program", "--headless", "script=t.log", "REPLAYPANSANDZOOMS",
                 "--start", "6", "--stop-after", "1", "--json"]) == 0
    assert _json_last(capsys) == runs["flags"]


def test_tripos_form_errors_name_the_argument(capsys) -> None:
    cases = [(["Log"], "argument 1 ('Log'): Log needs a value"),
             (["Log", "a", "LOG", "b"], "argument 3 ('LOG'): Log given twice"),
             (["5", "extra"], "argument 2 ('extra'): not a keyword of Log/k"),
             (["RecordPansAndZooms=yes"], "RecordPansAndZooms is a switch"),
             (["Checkpoint", "often"], "Checkpoint 'often': a number of generations"),
             (["Log", "a", "--log", "b"], "Log given twice: in the Tripos form and as --log")]
    for words, message in cases:
        assert main(["ca", "program", "--headless", "--stop-after", "1", *words]) == 2
        assert message in capsys.readouterr().err, words


def test_help_says_which_form_is_which(capsys) -> None:
    import pytest

    with pytest.raises(SystemExit):
        main(["ca", "program", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "the thesis's Tripos form" in text and "ours, the --flag form" in text
    assert "Log/k,RecordPansAndZooms/s,Checkpoint,Script/k,ReplayPansAndZooms/s" in text
    assert "RecordPansAndZooms/s = --record-pans" in text
