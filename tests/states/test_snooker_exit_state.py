"""``snooker play`` saved while Exit asks for a file name (the program's version 2): the
question is asked again by the program's own code at a load, the characters typed so far
kept as plain text; the name is finished after the load, Exit ends, and the session and
checkpoint are written where the user typed, as by the run that never saved. Once a name
has been given (Exit asks for the frames) no state is saved, and a state claiming that
question is refused; a version-1 state reads as version 2."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.emulator.machine.state_file import pack, unpack
from tests.states.support import assert_continues

# Escape opens Exit, y asks for the file (no --save), the name typed in two parts, Return,
# Return for all the frames
EVENTS = ("frames 3\nkey escape\nframes 2\nkey y\nframes 8\ntype ga\nframes 8\n"
          "type me.json\nframes 4\nkey return\nframes 4\nkey return\nframes 4\n")
SAVED = ("game.json", "game.cp")


def _argv(d: Path) -> list[str]:
    (d / "e.events").write_text(EVENTS)
    return ["snooker", "play", "--headless", "--events", "e.events"]


def _written(d: Path) -> dict[str, bytes]:
    out = {name: (d / name).read_bytes() for name in SAVED}
    for name in SAVED:
        (d / name).unlink()
    return out


def _program_part(state: Path) -> dict:
    head, _ = unpack(state.read_bytes(), "program")
    return head["values"]["program"]


@pytest.mark.parametrize(("at", "typed"), [(0.16, ""), (0.32, "ga")])
def test_a_state_saved_asking_for_the_exit_file_continues_and_saves_where_typed(
        monkeypatch, tmp_path: Path, at: float, typed: str) -> None:
    monkeypatch.chdir(tmp_path)
    argv = _argv(tmp_path)
    assert main(argv) == 0
    unbroken = _written(tmp_path)
    state = tmp_path / "p.c88state"
    with monkeypatch.context() as m:
        assert_continues(m, argv, at, state)
    values = _program_part(state)
    assert (values["mode"], values["text"]) == ("keys:exit_file", typed)
    assert "game" not in state.read_text("latin-1").replace(typed, "")
    assert _written(tmp_path) == unbroken  # (the load's run wrote them last)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["e.events", "p.c88state"]


def test_a_load_asks_the_programs_own_question_whatever_the_state_says(
        monkeypatch, tmp_path: Path) -> None:
    """The prompt and help text a state holds are not shown for Exit's question: the
    program asks it again (the typed characters are the state's)."""
    from camlab88.apps.snooker.program.program import Program

    monkeypatch.chdir(tmp_path)
    argv = _argv(tmp_path)
    state = tmp_path / "p.c88state"
    assert main([*argv, "--save-state", str(state), "--at", "0.32"]) == 0
    head, parts = unpack(state.read_bytes(), "program")
    values = head["values"]["program"]
    values["prompt"] = values["help_text"] = "Press Return to save to /etc/passwd"
    state.write_bytes(pack("program", head, parts))
    shown: list[str] = []
    real = Program.ask_again

    def noting(self, *a) -> None:
        real(self, *a)
        shown.append(self.help_text)

    monkeypatch.setattr(Program, "ask_again", noting)
    assert main([*argv, "--load-state", str(state)]) == 0
    assert shown == ["Save to which file? (the session; the checkpoint is written beside it\n"
                     "as NAME.cp)  Escape = stay in the program:\n> ga_"]


def test_no_state_is_saved_once_exit_has_its_file_name(monkeypatch, tmp_path: Path,
                                                        capsys) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "e.events").write_text(EVENTS.replace("key return\nframes 4\nkey return",
                                                      "key return\nframes 30\nkey return"))
    state = tmp_path / "p.c88state"
    code = main(["snooker", "play", "--headless", "--events", "e.events",
                 "--save-state", str(state), "--at", "0.62"])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 1 and not state.exists()
    assert str(state) in err[-1] and err[-1].endswith(
        "Exit has been given a file name (a state never names a file; it is saved once "
        "Exit's dialogue has ended)"), err


@pytest.mark.parametrize(("change", "refusal"), [
    ({"mode": "keys:exit_range"}, "the state asks which frames to save to a file it would "
                                  "name"),
    ({"text": "ga\nme"}, "the text typed holds a character no key types")])
def test_a_state_that_would_name_the_file_is_refused_in_one_line(
        monkeypatch, tmp_path: Path, change: dict, refusal: str) -> None:
    monkeypatch.chdir(tmp_path)
    argv = _argv(tmp_path)
    state = tmp_path / "p.c88state"
    assert main([*argv, "--save-state", str(state), "--at", "0.32"]) == 0
    _written(tmp_path)  # (by the run that saved the state, which went on to its end)
    head, parts = unpack(state.read_bytes(), "program")
    head["values"]["program"].update(change)
    state.write_bytes(pack("program", head, parts))
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--load-state", str(state)])
    text = str(stop.value)
    assert refusal in text and str(state) in text and "\n" not in text
    assert sorted(p.name for p in tmp_path.iterdir()) == ["e.events", "p.c88state"]


def test_a_version_1_state_reads_as_version_2_and_version_3_is_refused(
        monkeypatch, tmp_path: Path) -> None:
    """Version 2 only let a state be in Exit's questions: a version-1 state (saved outside
    them) loads as it is; a version with no migration is refused naming both."""
    monkeypatch.chdir(tmp_path)
    argv = _argv(tmp_path)
    state = tmp_path / "p.c88state"
    assert main([*argv, "--save-state", str(state), "--at", "0.04"]) == 0
    head, parts = unpack(state.read_bytes(), "program")
    assert head["state_version"] == 2
    state.write_bytes(pack("program", dict(head, state_version=1), parts))
    assert main([*argv, "--load-state", str(state)]) == 0
    state.write_bytes(pack("program", dict(head, state_version=3), parts))
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--load-state", str(state)])
    assert "version 3" in str(stop.value) and "version 2" in str(stop.value)
