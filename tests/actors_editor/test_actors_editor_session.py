"""The shipped recording of an editing session (examples/ca/actors_edit.session) replays
with --check, screen hash for screen hash; its script is the editor's demo script."""

from __future__ import annotations

from pathlib import Path

from camlab88.apps.actors.editor.demo import demo_events
from camlab88.cli import main
from camlab88.protocols.session import read

SESSION = Path(__file__).resolve().parents[2] / "examples" / "ca" / "actors_edit.session"


def test_the_shipped_editing_session_replays_with_check(capsys) -> None:
    rec = read(SESSION)
    assert rec.argv[:2] == ["ca", "actors"]
    assert rec.files["actors_edit.events"].decode() == demo_events()
    assert main(["replay", str(SESSION), "--check", "--headless"]) == 0
    assert f"all {len(rec.hashes) + 1} screen hashes agree" in capsys.readouterr().out


def test_record_then_replay_of_an_editing_session(tmp_path: Path, monkeypatch,
                                                  capsys) -> None:
    monkeypatch.chdir(tmp_path)
    Path("e.events").write_text("click left 32 472\nwait 3\nclick left 128 400\nwait 5\n"
                                "key s\nwait 2\n", encoding="utf-8")
    assert main(["ca", "actors", "a.actors", "--headless", "--events", "e.events",
                 "--record", "a.session"]) == 0
    saved = Path("a.actors").read_text(encoding="utf-8")
    Path("a.actors").unlink()
    assert main(["replay", "a.session", "--check", "--headless"]) == 0
    assert "screen hashes agree" in capsys.readouterr().out
    assert not Path("a.actors").exists()  # the replay saved in its scratch directory
    assert "lathe 0 0  0.3 0.225" in saved
