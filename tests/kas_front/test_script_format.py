"""One KAS script format, time optional: the same file drives the editor model
(``kas edit-script``) and the editor on the Sigma (``kas edit --script``)."""

from __future__ import annotations

from pathlib import Path

from camlab88.apps.kas import files
from camlab88.apps.kas.events import parse_script
from camlab88.cli import main
from tests.kas_front.helpers import DATA

UNTIMED = Path(__file__).resolve().parents[1] / "data" / "kas" / "walk_edit_script.txt"


def test_an_untimed_model_script_runs_on_the_sigma(tmp_path: Path, capsys) -> None:
    model, front = tmp_path / "m.kas", tmp_path / "f.kas"
    assert main(["kas", "edit-script", str(UNTIMED), "--out", str(model)]) == 0
    # the same script; on the Sigma its last key, Esc with no command to cancel, asks
    # whether to save and quit: y does
    script = tmp_path / "s.txt"
    script.write_text(UNTIMED.read_text(encoding="utf-8") + "key y\n", encoding="utf-8")
    assert main(["kas", "edit", str(front), "--script", str(script), "--headless"]) == 0
    capsys.readouterr()
    a, b = files.load_keyframe(model), files.load_keyframe(front)
    assert len(a.chains) == len(b.chains) > 0


def test_a_timed_sigma_script_is_read_by_the_model() -> None:
    timed = (DATA / "edit_all.txt").read_text(encoding="utf-8")
    events = parse_script("0.5 move 1 2\n+0.1 down 1 2\n3 wait\nwait\nup 1 2\n", "t.txt")
    assert len(events) == 3
    assert parse_script(timed, "edit_all.txt")  # every line of the Sigma script is understood


def test_bad_times_name_the_line() -> None:
    import pytest

    for text in ("1/0 move 1 2", "-1 move 1 2", "+x move 1 2"):
        with pytest.raises(ValueError, match="t.txt:1: bad event"):
            parse_script(text, "t.txt")
