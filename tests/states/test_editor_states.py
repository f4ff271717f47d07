"""The editors' save states (emulator.harness.input_log): kas edit, kas path, kas paint, the
snooker camera tool and the CA actors editor keep the input that made their session and run
a fresh session again with it. Saved mid-session, loaded, continued: the same frames as the
unbroken run; a load writes nothing; a log that does not rebuild the saved picture is
refused in one line."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from camlab88.cli import main
from camlab88.emulator.machine.state_file import pack, unpack
from tests.states.support import assert_continues, frame_logs, inputs_of, saved_place


def _kas_edit(d: Path) -> list[str]:
    inputs_of("tests/data/sessions/kas_edit.session", d)
    return ["kas", "edit", str(d / "key.kas"), "--script", str(d / "edit_all.txt"),
            "--headless", "--seed", "1"]


def _kas_path(d: Path) -> list[str]:
    inputs_of("examples/figures/fig-3.6.session", d)
    return ["kas", "path", str(d / "flag_a.kas"), str(d / "flag_b.kas"), "--out",
            str(d / "flag_path.kas"), "--no-library", "--headless", "--script",
            str(d / "fig-3.6.script")]


@pytest.mark.parametrize("at", [0.5, 3.0])
def test_kas_edit_continues_from_a_state(monkeypatch, tmp_path: Path, at: float) -> None:
    assert_continues(monkeypatch, _kas_edit(tmp_path), at, tmp_path / "e.c88state")


def test_kas_edit_starts_from_the_states_keyframe_not_from_file(monkeypatch, tmp_path: Path,
                                                                capsys) -> None:
    """FILE is where F2 saves (the command line's): the state keeps the keyframe the session
    started from, so a FILE saved since (or replaced) changes nothing at a load."""
    argv = _kas_edit(tmp_path)
    state = tmp_path / "e.c88state"
    assert main([*argv, "--save-state", str(state), "--at", "2"]) == 0
    before = state.read_bytes()
    (tmp_path / "key.kas").write_text("KAS keyframe 1\nchains 0\nend\n")  # another drawing
    assert_continues(monkeypatch, argv, 2.0, state)
    head, _ = unpack(before, "program")
    assert str(tmp_path / "key.kas") not in json.dumps(head), "the save path is in the state"


def test_kas_path_continues_from_a_state(monkeypatch, tmp_path: Path) -> None:
    assert_continues(monkeypatch, _kas_path(tmp_path), 0.5, tmp_path / "p.c88state")


def test_a_load_writes_nothing_while_the_session_runs_again(monkeypatch,
                                                            tmp_path: Path) -> None:
    """The session's saves before the state was saved are not made again at a load: the
    loaded run writes --out once, at its own end (as the unbroken run did after the save)."""
    from camlab88.apps.kas import files

    argv = _kas_path(tmp_path)
    state = tmp_path / "p.c88state"
    seen: list[Path] = []
    real = files.save_path

    def noting(path, sample) -> None:
        seen.append(Path(path))
        real(path, sample)

    monkeypatch.setattr(files, "save_path", noting)
    assert main([*argv, "--save-state", str(state), "--at", "0.7"]) == 0
    unbroken, seen[:] = list(seen), []
    assert main([*argv, "--load-state", str(state)]) == 0
    assert seen == unbroken == [tmp_path / "flag_path.kas"]


def test_a_log_that_does_not_rebuild_the_saved_picture_is_refused(tmp_path: Path,
                                                                  capsys) -> None:
    argv = _kas_edit(tmp_path)
    state = tmp_path / "e.c88state"
    assert main([*argv, "--save-state", str(state), "--at", "2"]) == 0
    head, parts = unpack(state.read_bytes(), "program")
    head["values"]["input"]["events"].append([1, ["key", "x", "x", [], 0, 0, 0, False, []]])
    state.write_bytes(pack("program", head, parts))
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--load-state", str(state)])
    assert "does not rebuild the saved picture" in str(stop.value)
    assert str(state) in str(stop.value) and "\n" not in str(stop.value)


def _kas_paint(d: Path) -> list[str]:
    inputs_of("examples/figures/fig-3.7.session", d)
    return ["kas", "paint", str(d / "face.kas"), "--headless", "--script",
            str(d / "fig-3.7.script")]


@pytest.mark.parametrize("at", [0.3, 2.0])
def test_kas_paint_continues_from_a_state(monkeypatch, tmp_path: Path, at: float) -> None:
    assert_continues(monkeypatch, _kas_paint(tmp_path), at, tmp_path / "k.c88state")


CAMERA = Path(__file__).resolve().parents[1] / "data" / "snooker_camera"
CAMERA_EVENTS = ("wait 10\nkey down\nkey down\ntype veiw\nwait 10\nmove 210 550\npress left\n"
                 "release left\nwait 10\nkey down\ntype xx\nwait 10\n")


def _camera(d: Path) -> list[str]:
    import shutil

    shutil.copy(CAMERA / "thesis_example.ccl", d / "cam.ccl")
    (d / "ev.txt").write_text(CAMERA_EVENTS)
    return ["snooker", "camera", str(d / "cam.ccl"), str(CAMERA / "pink_shot.checkpoint"),
            "--events", str(d / "ev.txt"), "--headless"]


@pytest.mark.parametrize("at", [0.1, 0.5])
def test_the_camera_tool_continues_from_a_state(monkeypatch, tmp_path: Path,
                                                at: float) -> None:
    assert_continues(monkeypatch, _camera(tmp_path), at, tmp_path / "c.c88state")


def test_the_camera_tool_rebuilds_from_the_texts_it_read_not_the_disk(
        monkeypatch, tmp_path: Path) -> None:
    """Another editor saved SCRIPT during the session: the state keeps the text the tool
    read then and the text it started from; a load reads neither from the disk (which
    holds something else by then)."""
    import os

    from camlab88.emulator.harness import plugins
    from camlab88.emulator.harness.loop import Plugin

    argv = _camera(tmp_path)
    script = tmp_path / "cam.ccl"

    class Editor(Plugin):  # another editor saves the script while the tool runs
        def post_tick(self, harness) -> None:
            if harness.ticks == 5 and harness.options.state.load is None:
                script.write_text(":focal length of 300\n")
                os.utime(script, ns=(1, 3))

    real = plugins.standard_plugins
    monkeypatch.setattr(plugins, "standard_plugins", lambda o: [*real(o), Editor()])
    state = tmp_path / "c.c88state"
    with frame_logs(monkeypatch) as runs:
        assert main([*argv, "--save-state", str(state), "--at", "0.4"]) == 0
        head, _ = unpack(state.read_bytes(), "program")
        assert [t for _, t in head["values"]["input"]["texts"]] == [":focal length of 300\n"]
        script.write_text("garbage that would not interpret\n")  # neither text is on disk
        assert main([*argv, "--load-state", str(state)]) == 0
    full, rest = runs
    k = saved_place(state)[1]
    assert rest.pop("ticks") and full.pop("ticks")
    assert {n: h for n, h in full.items() if n > k} == rest


ACTORS_EVENTS = ("wait 5\nkey tab\nwait 3\nclick left 32 472\nwait 3\nclick left 128 400\n"
                 "wait 3\nkey s\nwait 5\nclick left 96 300\nwait 3\nclick left 64 250\n"
                 "wait 5\n")


def _actors(d: Path) -> list[str]:
    (d / "m.actors").write_text("rules maze\nactor 1 wall\n  colour 9 9 9\n  box 1 1 1\nend\n",
                                encoding="utf-8")
    (d / "e.events").write_text(ACTORS_EVENTS)
    return ["ca", "actors", str(d / "m.actors"), "--headless", "--events", str(d / "e.events")]


@pytest.mark.parametrize("at", [0.1, 0.4])
def test_the_actors_editor_continues_from_a_state(monkeypatch, tmp_path: Path,
                                                  at: float) -> None:
    """Saved before and after its own save (key s) rewrote FILE: a load starts from the
    FILE the session began with, kept in the state, and its save writes nothing then."""
    argv = _actors(tmp_path)
    path = tmp_path / "m.actors"
    first = path.read_text()
    assert_continues(monkeypatch, argv, at, tmp_path / "a.c88state")
    assert path.read_text() != first  # the runs saved FILE (rewritten: not what began them)


def test_the_actors_editors_save_is_not_made_again_at_a_load(monkeypatch,
                                                             tmp_path: Path) -> None:
    from camlab88.apps.actors.editor import program

    argv = _actors(tmp_path)
    state = tmp_path / "a.c88state"
    writes: list[str] = []
    real = program.write_actors
    monkeypatch.setattr(program, "write_actors",
                        lambda path, s: (writes.append(str(path)), real(path, s)))
    assert main([*argv, "--save-state", str(state), "--at", "0.4"]) == 0
    assert writes == [str(tmp_path / "m.actors")]  # key s, before the state was saved
    writes.clear()
    assert main([*argv, "--load-state", str(state)]) == 0
    assert writes == []


def test_a_live_tablet_session_saves_its_tablets_input() -> None:
    """Its reports are kept in the log as the tablet tape's entries, tick by tick (the same
    entries a recording keeps; tests/states/test_tablet_states.py loads them back)."""
    from types import SimpleNamespace

    from camlab88.emulator.harness.input_log import picture_hash
    from camlab88.emulator.harness.sigma import SigmaProgramTarget

    tape = [b'[[0,"open",{"kind":"hid","name":"t","vid":1,"pid":2,"descriptor":null}]]',
            b'[[1,"raw","0a0b"]]']
    pointer = SimpleNamespace(live=True, protocol="hid", emulated=False,
                              take_state_tape=lambda: tape.pop(0) if tape else b"")
    session = SimpleNamespace(pointer_source=pointer)
    target = SigmaProgramTarget(SimpleNamespace(session=session), "t", "", frozenset(), [],
                                True)
    target.log.ticked()
    target.log.ticked()
    target.picture = lambda: picture_hash(np.zeros((2, 2, 3), np.uint8))
    assert target.state_values()["tablet"] == {
        "protocol": "hid", "emulated": False,
        "tape": b'[[0,"open",{"kind":"hid","name":"t","vid":1,"pid":2,"descriptor":null}],'
                b'[1,"raw","0a0b"]]'}


def test_a_rainbow_editor_with_a_tablet_saves_its_tablets_input() -> None:
    """The camera tool's and the actors editor's target (RainbowTarget.keep_input): a tablet
    the command polls is kept in the log (its tape), not refused."""
    from types import SimpleNamespace

    from camlab88.emulator.harness.rainbow import RainbowTarget
    from camlab88.emulator.machine import RainbowMachine

    target = RainbowTarget(RainbowMachine(), lambda: True, "t", "")
    target.keep_input()
    assert target.state_values()["tablet"] is None  # without a tablet: none
    target = RainbowTarget(RainbowMachine(), lambda: True, "t", "")
    target.tablet = SimpleNamespace(protocol="summa-mm", keep_for_state=lambda: None,
                                    take_state_tape=lambda: b'[[0,"raw","00"]]')
    target.keep_input()
    target.tick()
    assert target.state_values()["tablet"] == {"protocol": "summa-mm", "emulated": False,
                                               "tape": b'[[0,"raw","00"]]'}


def test_an_editor_loads_a_state_into_a_fresh_run_only() -> None:
    from camlab88.emulator.harness.input_log import InputLog, picture_hash
    from camlab88.emulator.machine.state_file import MachineStateError

    log = InputLog()
    log.ticked()
    values = InputLog().values(picture_hash(np.zeros((2, 2, 3), np.uint8)))
    with pytest.raises(MachineStateError, match="fresh run only"):
        log.rebuild(values, lambda e: None, lambda: True, lambda: True, lambda: "")


def test_a_log_out_of_tick_order_is_refused() -> None:
    from camlab88.emulator.harness.input_log import InputLog
    from camlab88.emulator.machine.state_file import MachineStateError

    key = ["key", "a", "a", [], 0, 0, 0, False, []]
    for events in ([[3, key], [1, key]], [[5, key]]):
        values = {"ticks": 5, "events": events, "texts": [], "picture": "", "tablet": None}
        with pytest.raises(MachineStateError, match="not in tick order"):
            InputLog().rebuild(values, lambda e: None, lambda: True, lambda: True,
                               lambda: "")


def test_a_log_claims_at_most_max_ticks() -> None:
    """A load runs every tick again: the count a state may claim is bounded."""
    from camlab88.base.plainstate import StateValueError, decode
    from camlab88.emulator.harness.input_log import MAX_TICKS, SCHEMA

    values = {"ticks": MAX_TICKS + 1, "events": [], "texts": [], "picture": "",
              "tablet": None}
    with pytest.raises(StateValueError, match="state.ticks"):
        decode(SCHEMA, values, {})
    assert decode(SCHEMA, dict(values, ticks=MAX_TICKS), {})["ticks"] == MAX_TICKS
