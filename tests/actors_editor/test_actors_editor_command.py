"""``camlab88 ca actors``: the rule set comes from the file when --rules is not given, a file
that does not load ends the run with status 1 and its file:line:col on stderr, and a
--screenshot run writes no file."""

from __future__ import annotations

from pathlib import Path

from camlab88.apps.actors.model import read_actors
from camlab88.cli import main


def _events(tmp_path: Path, text: str) -> str:
    path = tmp_path / "e.events"
    path.write_text(text, encoding="utf-8")
    return str(path)


TWO_POINTS = "click left 32 472\nwait 1\nclick left 128 400\nwait 1\n"


def test_the_rules_named_in_the_file_give_the_cell_types(tmp_path: Path) -> None:
    path = tmp_path / "m.actors"
    path.write_text("rules maze\nactor 1 wall\n  colour 9 9 9\n  box 1 1 1\nend\n",
                    encoding="utf-8")
    events = _events(tmp_path, "key tab\nkey tab\nwait 1\n" + TWO_POINTS + "key s\nwait 1\n")
    assert main(["ca", "actors", str(path), "--headless", "--events", events]) == 0
    got = read_actors(path)
    assert got.rules == "maze" and sorted(got.actors) == [1, 3]  # maze has states 1..3
    assert got.actors[1].name == "wall"


def test_a_bad_file_ends_with_status_1_naming_file_line_and_column(tmp_path: Path,
                                                                    capsys) -> None:
    path = tmp_path / "bad.actors"
    path.write_text("rules life\nactor 1 pawn\n  colour 1 2 x\nend\n", encoding="utf-8")
    assert main(["ca", "actors", str(path), "--headless", "--stop-after", "3"]) == 1
    err = capsys.readouterr().err
    assert f"{path}:3:" in err and "Traceback" not in err


def test_a_screenshot_run_writes_no_file(tmp_path: Path) -> None:
    path = tmp_path / "s.actors"
    events = _events(tmp_path, TWO_POINTS + "key s\nwait 1\n")
    assert main(["ca", "actors", str(path), "--headless", "--events", events,
                 "--screenshot", str(tmp_path / "s.png")]) == 0
    assert (tmp_path / "s.png").exists() and not path.exists()
