"""Every program's whole state (device + program + input decoders) saved at a random frame of a
random scripted session and loaded into a freshly built program continues with exactly the
frames of the uninterrupted run."""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from camlab88.cli import main
from tests.states.support import assert_continues, assert_file_dialogue_refused, inputs_of

STATEFUL = settings(max_examples=3, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.function_scoped_fixture])

# --- scripted input: the Rainbow script language and the KAS event language ----------------
_x, _y = st.integers(0, 767), st.integers(0, 575)
_button = st.sampled_from(["left", "middle", "right"])
rainbow_line = st.one_of(
    st.builds(lambda x, y: f"move {x} {y}", _x, _y),
    st.builds(lambda b, x, y: f"click {b} {x} {y}", _button, _x, _y),
    st.builds(lambda b, x, y: f"press {b} {x} {y}\nframes 2\nrelease {b} {x} {y}",
              _button, _x, _y),
    st.builds(lambda n: f"frames {n}", st.integers(1, 6)),
    st.sampled_from(["key space", "key return", "key escape", "type 3"]))
rainbow_script = st.lists(rainbow_line, min_size=3, max_size=14).map(
    lambda lines: "frames 3\n" + "\n".join(lines) + "\nframes 4\n")

fraction_of_run = st.floats(0.05, 0.8)


# hypothesis runs each example in one test call, so each gets its own directory under one
# that is removed when the test process ends (tmp_path would be shared by the examples)
_SCRATCH = tempfile.TemporaryDirectory(prefix="camlab88-state-tests-")


def _scratch() -> Path:
    return Path(tempfile.mkdtemp(dir=_SCRATCH.name))


@STATEFUL
@given(when=fraction_of_run, mode=st.sampled_from(["--realtime", "--every"]))
def test_kas_view_continues_from_a_state(monkeypatch, when: float, mode: str) -> None:
    d = _scratch()
    assert main(["kas", "demo", "--out", str(d / "seq.kas")]) == 0
    argv = ["kas", "view", str(d / "seq.kas"), "--headless", mode]
    assert_continues(monkeypatch, argv, when * 2, d / "v.c88state")


@STATEFUL
@given(script=rainbow_script, when=fraction_of_run)
def test_snooker_play_continues_from_a_state(monkeypatch, script: str, when: float) -> None:
    d = _scratch()
    (d / "e.events").write_text(script)
    argv = ["snooker", "play", "--headless", "--events", str(d / "e.events")]
    assert_continues(monkeypatch, argv, when * 0.3, d / "p.c88state")


@STATEFUL
@given(when=fraction_of_run)
def test_snooker_visualise_continues_from_a_state(monkeypatch, when: float) -> None:
    d = inputs_of("examples/figures/fig-6.7.session", _scratch())
    argv = ["snooker", "visualise", str(d / "pink_shot.cp"), str(d / "example.views"),
            "--headless"]
    assert_continues(monkeypatch, argv, when * 2.8, d / "v.c88state")


@STATEFUL
@given(when=fraction_of_run, last=st.integers(10, 74))
def test_snooker_replay_continues_from_a_state(monkeypatch, when: float, last: int) -> None:
    d = inputs_of("examples/figures/fig-6.7.session", _scratch())
    argv = ["snooker", "replay", str(d / "pink_shot.cp"), "--headless", "--last", str(last)]
    assert_continues(monkeypatch, argv, when * last / 25, d / "r.c88state")


@STATEFUL
@given(script=rainbow_script, when=fraction_of_run,
       pattern=st.sampled_from(["glider", "gosper_gun", "boat"]))
def test_ca_program_continues_from_a_state(monkeypatch, script: str, when: float,
                                           pattern: str) -> None:
    d = _scratch()
    (d / "e.events").write_text(script)
    argv = ["ca", "program", "--headless", "--pattern", pattern, "--events", str(d / "e.events")]
    assert_continues(monkeypatch, argv, when * 0.3, d / "c.c88state")


@STATEFUL
@given(data=st.binary(min_size=0, max_size=600), when=fraction_of_run)
def test_sigma_run_continues_from_a_state(monkeypatch, data: bytes, when: float) -> None:
    d = inputs_of("tests/data/sessions/sigma_run.session", _scratch())
    (d / "in.sigma").write_bytes((d / "picture.sigma").read_bytes() + data)  # and noise
    argv = ["sigma", "run", "--headless", "--in", str(d / "in.sigma"), "--seconds", "2"]
    assert_continues(monkeypatch, argv, when * 2, d / "s.c88state")


@STATEFUL
@given(when=fraction_of_run, demo=st.sampled_from(["pads", "shelf"]))
def test_rainbow_run_continues_from_a_state(monkeypatch, when: float, demo: str) -> None:
    d = _scratch()
    argv = ["rainbow", "run", "--headless", "--stop-after", "40", "--demo", demo]
    assert_continues(monkeypatch, argv, when * 0.8, d / "r.c88state")


@pytest.mark.parametrize("at", [0.0, 0.3])
def test_a_ca_state_saved_with_a_menu_held_continues(monkeypatch, tmp_path: Path,
                                                     at: float) -> None:
    """The middle button holds a menu open (plain state: which menu, where, what is
    highlighted) that the script answers after the save."""
    (tmp_path / "e.events").write_text(
        "frames 3\npress middle 400 300\nframes 20\nrelease middle 400 300\nframes 4\n"
        "click right 300 300\nframes 6\n")
    argv = ["ca", "program", "--headless", "--pattern", "glider", "--events",
            str(tmp_path / "e.events")]
    assert_continues(monkeypatch, argv, at + 0.1, tmp_path / "c.c88state")


def _populate_events() -> str:
    from camlab88.apps.ca.program.demo import choose, leave_editing

    return ("frames 3\n" + leave_editing() + choose("Randomly populate") +
            "frames 2\nmove 350 300\nclick right 350 300\nframes 2\nmove 450 380\n"
            "click right 450 380\nframes 20\ntype 0.5\nkey return\nframes 2\ntype 1:1\n"
            "key return\nframes 6\n")


@pytest.mark.parametrize(("at", "answered", "corner"), [(0.12, [], False), (0.16, [], True),
                                                       (0.3, ["rect"], False)])
def test_a_ca_state_saved_in_a_dialogue_continues(monkeypatch, tmp_path: Path, at: float,
                                                  answered: list[str], corner: bool) -> None:
    """Randomly populate, saved asking for the rectangle, with its first corner given, and
    with the rectangle answered (the density asked): the dialogue is made again from its
    name and answers through the program's own code and the script answers the rest."""
    from camlab88.emulator.machine.state_file import unpack

    (tmp_path / "e.events").write_text(_populate_events())
    argv = ["ca", "program", "--headless", "--pattern", "glider", "--events",
            str(tmp_path / "e.events")]
    state = tmp_path / "c.c88state"
    assert_continues(monkeypatch, argv, at, state)
    head, _ = unpack(state.read_bytes(), "program")
    dialogue = head["values"]["program"]["dialogue"]
    assert dialogue["name"] == "Randomly populate"
    assert [a["kind"] for a in dialogue["answers"]] == answered
    assert (dialogue["corner"] is not None) == corner


def test_a_ca_state_whose_answers_end_its_dialogue_is_refused(tmp_path: Path) -> None:
    """A dialogue is only made again up to a question: answers that would end it (and so
    act) are refused in one line."""
    from camlab88.emulator.machine.state_file import pack, unpack

    (tmp_path / "e.events").write_text(_populate_events())
    argv = ["ca", "program", "--headless", "--pattern", "glider", "--events",
            str(tmp_path / "e.events")]
    state = tmp_path / "c.c88state"
    assert main([*argv, "--save-state", str(state), "--at", "0.3"]) == 0
    head, parts = unpack(state.read_bytes(), "program")
    head["values"]["program"]["dialogue"]["answers"].append(
        {"kind": "none", "text": "", "ints": []})  # cancels the density question: it ends
    state.write_bytes(pack("program", head, parts))
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--load-state", str(state)])
    assert "the answers given end the dialogue 'Randomly populate'" in str(stop.value)
    assert "\n" not in str(stop.value)


def _file_dialogue_events(item: str, before_name: str, name: str, after: str) -> str:
    from camlab88.apps.ca.program.demo import choose, leave_editing

    return ("frames 3\n" + leave_editing() + choose(item) + before_name +
            f"frames 20\ntype {name}\nkey return\n" + after + "frames 6\n")


def _dialogue_of(state: Path) -> dict:
    from camlab88.emulator.machine.state_file import unpack

    head, _ = unpack(state.read_bytes(), "program")
    return head["values"]["program"]["dialogue"]


@pytest.mark.parametrize("item", ["Change rules", "Load pattern"])
def test_a_ca_state_saved_asking_for_a_file_continues(monkeypatch, tmp_path: Path,
                                                      item: str) -> None:
    """Change rules and Load pattern, saved while they ask for the file: made again with no
    answer, the script names the file after the load."""
    name = "life" if item == "Change rules" else "glider"
    after = "" if item == "Change rules" else "frames 2\nclick right 420 320\nframes 2\n"
    (tmp_path / "e.events").write_text(_file_dialogue_events(item, "", name, after))
    argv = ["ca", "program", "--headless", "--pattern", "glider", "--events",
            str(tmp_path / "e.events")]
    state = tmp_path / "c.c88state"
    assert_continues(monkeypatch, argv, 0.3, state)
    assert _dialogue_of(state) == {"name": item, "arg": 0, "answers": [], "corner": None,
                                   "menu": None}


def test_a_ca_state_saved_in_save_pattern_before_its_name_continues(monkeypatch,
                                                                     tmp_path: Path) -> None:
    """Save pattern, saved with its rectangle answered, asking for the file's name: the
    name comes from the script after the load, never from the state; the file is written."""
    rect = ("frames 2\nmove 350 300\nclick right 350 300\nframes 2\nmove 450 380\n"
            "click right 450 380\n")
    saved = tmp_path / "p"
    (tmp_path / "e.events").write_text(_file_dialogue_events(
        "Save pattern", rect, str(saved), "frames 2\nclick right 400 340\n"))
    argv = ["ca", "program", "--headless", "--pattern", "glider", "--events",
            str(tmp_path / "e.events")]
    state = tmp_path / "c.c88state"
    assert_continues(monkeypatch, argv, 0.4, state)
    dialogue = _dialogue_of(state)
    assert dialogue["name"] == "Save pattern"
    assert [a["kind"] for a in dialogue["answers"]] == ["rect"]


def test_a_ca_state_giving_a_file_dialogue_its_file_name_is_refused(monkeypatch,
                                                                   tmp_path: Path) -> None:
    """A state never names a file: answers reaching a file dialogue's file question are
    refused in one line before any step of it runs (the file never read)."""
    from camlab88.emulator.machine.state_file import pack, unpack

    (tmp_path / "e.events").write_text(_file_dialogue_events("Load pattern", "", "glider",
                                                             ""))
    argv = ["ca", "program", "--headless", "--pattern", "glider", "--events",
            str(tmp_path / "e.events")]
    state = tmp_path / "c.c88state"
    assert main([*argv, "--save-state", str(state), "--at", "0.3"]) == 0
    head, parts = unpack(state.read_bytes(), "program")
    outside = tmp_path / "outside.rle"
    outside.write_text("x = 1, y = 1\no!\n")
    head["values"]["program"]["dialogue"]["answers"].append(
        {"kind": "text", "text": str(outside), "ints": []})
    state.write_bytes(pack("program", head, parts))
    opened = []
    real_open = open

    def watching(path, *a, **k):
        opened.append(str(path))
        return real_open(path, *a, **k)

    import builtins

    monkeypatch.setattr(builtins, "open", watching)
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--load-state", str(state)])
    monkeypatch.undo()
    assert "the dialogue 'Load pattern' would be given a file name by the state" in \
        str(stop.value)
    assert "\n" not in str(stop.value)
    assert str(outside) not in opened


def test_a_ca_state_is_not_saved_once_a_file_dialogue_has_its_name(tmp_path: Path,
                                                                    capsys) -> None:
    """Save pattern given its file's name (asking for the reference point): --save-state
    fails the run in one line naming the state file (status 1)."""
    rect = ("frames 2\nmove 350 300\nclick right 350 300\nframes 2\nmove 450 380\n"
            "click right 450 380\n")
    (tmp_path / "e.events").write_text(_file_dialogue_events(
        "Save pattern", rect, str(tmp_path / "p"), "frames 30\n"))
    assert_file_dialogue_refused(tmp_path / "e.events", "Save pattern", capsys)


def test_a_save_state_that_cannot_be_written_ends_the_run_with_status_1(
        tmp_path: Path, capsys, monkeypatch) -> None:
    import errno

    from camlab88.emulator.harness import state_plugin

    def full(path, data):
        raise OSError(errno.ENOSPC, "No space left on device", str(path))

    monkeypatch.setattr(state_plugin, "write_atomic", full)
    state = tmp_path / "s.c88state"
    for argv in (["sigma", "run", "--headless", "--seconds", "0.1"],
                 ["rainbow", "run", "--headless", "--stop-after", "3"]):
        assert main([*argv, "--save-state", str(state)]) == 1
        err = capsys.readouterr().err.strip().splitlines()
        assert f"--save-state {state}: no state saved" in err[-1]
        assert "No space left on device" in err[-1]
