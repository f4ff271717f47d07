"""``camlab88 ca program`` headless with scripted input; the demo function."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from PIL import Image

from apps.ca.program.demo import choose, demo_events, leave_editing
from apps.ca.program.program import CAProgram, Options
from apps.ca.program.script_events import parse, play
from camlab88.cli import main
from emulator.rainbow.session import in_process


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
    session = in_process()
    program = CAProgram(session.client, Options(rules="life", pattern="gosper_gun"))
    play(parse(demo_events(60), "<ca demo>"), session.inject, program.frame,
         lambda: program.finished)
    stats = program.session.statistics()
    assert stats["generation"] == 60 and stats["population"] == 46  # the gun and two gliders
    assert stats["viewport"][2] == "8"
