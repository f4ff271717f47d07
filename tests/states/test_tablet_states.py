"""An editor fed by a tablet saves its state (emulator.harness.input_log: the tablet tape's
entries, as a recording keeps them) and a load decodes that tape through the protocol parser
while the session runs again, then carries on with the command line's ``--tablet``: the
frames after the save are the unbroken run's. A state holding a tablet's input is refused
by a run without a tablet or with another protocol, and damaged tablet input in one line."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.emulator.machine.state_file import pack, unpack
from tests.states.support import assert_continues

# the pen goes down at 0.4 s and up at 1.0 s; F2 saves the keyframe at 1.5 s
SCRIPT = ("0.2 move 0 0\n0.4 down 0 0\n0.6 down 1 1\n0.8 down 2 1\n1.0 up 2 1\n"
          "1.2 move 3 3\n1.5 key f2\n2.0 wait\n")


@pytest.fixture
def kas_edit(tmp_path: Path, monkeypatch) -> list[str]:
    """kas edit with the emulated tablet driven by its script (no calibration: the config
    directory is the test's own)."""
    monkeypatch.setenv("CAMLAB88_CONFIG_DIR", str(tmp_path / "config"))
    (tmp_path / "s.txt").write_text(SCRIPT)
    return ["kas", "edit", str(tmp_path / "k.kas"), "--tablet", "emulated:summa-mm",
            "--headless", "--script", str(tmp_path / "s.txt")]


def _saved(argv: list[str], state: Path, at: str = "0.7") -> tuple[dict, dict]:
    assert main([*argv, "--save-state", str(state), "--at", at]) == 0
    return unpack(state.read_bytes(), "program")


def _refusal(argv: list[str], state: Path) -> str:
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--load-state", str(state)])
    said = str(stop.value)
    assert str(state) in said and "\n" not in said, said
    return said


@pytest.mark.parametrize("at", [0.7, 1.3])
def test_kas_edit_with_a_tablet_continues_from_a_state(monkeypatch, kas_edit, tmp_path: Path,
                                                       at: float) -> None:
    """Saved mid-stroke (pen down) and after it: the loaded run's frames are the unbroken
    run's, the stroke drawn before the save read from the state's tape."""
    state = tmp_path / "e.c88state"
    assert_continues(monkeypatch, kas_edit, at, state)
    head, parts = unpack(state.read_bytes(), "program")
    tablet = head["values"]["input"]["tablet"]
    assert (tablet["protocol"], tablet["emulated"]) == ("summa-mm", True)
    assert b'"raw"' in parts[tablet["tape"]] and b'"open"' in parts[tablet["tape"]]


def test_the_stroke_before_the_save_comes_from_the_tape(kas_edit, tmp_path: Path,
                                                        capsys) -> None:
    """Saved after the stroke (no pen down after it): the loaded run's keyframe holds it,
    decoded from the state's tape; with the tape's reports taken out (the tablet opened,
    so the script's mouse is not read) it holds none."""
    import json

    state = tmp_path / "e.c88state"
    head, parts = _saved(kas_edit, state, "1.1")
    assert "1 chains, 3 points" in capsys.readouterr().out
    assert main([*kas_edit, "--load-state", str(state)]) == 0
    assert "1 chains, 3 points" in capsys.readouterr().out
    name = head["values"]["input"]["tablet"]["tape"]
    parts[name] = json.dumps([e for e in json.loads(parts[name]) if e[1] != "raw"]).encode()
    state.write_bytes(pack("program", head, parts))
    assert main([*kas_edit, "--load-state", str(state)]) == 0
    assert "0 chains, 0 points" in capsys.readouterr().out


def test_a_state_with_a_tablets_input_needs_a_tablet_of_its_protocol(kas_edit,
                                                                     tmp_path: Path) -> None:
    state = tmp_path / "e.c88state"
    _saved(kas_edit, state)
    bare = [w for w in kas_edit if w not in ("--tablet", "emulated:summa-mm")]
    assert "holds a summa-mm tablet's input: load it with --tablet" in _refusal(bare, state)
    other = [w if w != "emulated:summa-mm" else "emulated:wacom4" for w in kas_edit]
    assert "this run's --tablet is wacom4" in _refusal(other, state)


@pytest.mark.parametrize(("tape", "said"), [
    (b"not json", "state.tablet.tape"),
    (b'[[0,"raw",5]]', "a raw entry's payload is hex"),
    (b'[[3,"raw","00"],[1,"raw","00"]]', "not in poll order"),
    (b'[[99999,"raw","00"]]', "an entry at poll 99999"),
    (b"[" * 5000 + b"]" * 5000, "state.tablet.tape"),
    (b'[[0,"calibration",{"device":"x","top_left":[0,0],"bottom_right":[9,9]}]]',
     "another calibration"),
])
def test_damaged_tablet_input_is_refused_in_one_line(kas_edit, tmp_path: Path, tape: bytes,
                                                     said: str) -> None:
    state = tmp_path / "e.c88state"
    head, parts = _saved(kas_edit, state)
    parts[head["values"]["input"]["tablet"]["tape"]] = tape
    state.write_bytes(pack("program", head, parts))
    assert said in _refusal(kas_edit, state)


def test_a_tablet_tape_past_its_bound_is_refused_before_it_is_read(kas_edit,
                                                                   tmp_path: Path) -> None:
    from camlab88.emulator.harness.input_log import MAX_TABLET_TAPE

    state = tmp_path / "e.c88state"
    head, parts = _saved(kas_edit, state)
    parts[head["values"]["input"]["tablet"]["tape"]] = b" " * (MAX_TABLET_TAPE + 1)
    state.write_bytes(pack("program", head, parts))
    assert "names no binary part of at most" in _refusal(kas_edit, state)


def test_an_editors_state_of_version_1_is_read_as_holding_no_tablet_input(
        kas_edit, tmp_path: Path, monkeypatch) -> None:
    """Version 1 (before the tablet's input was kept: a tablet session did not save) loads
    through the migration, into a run with or without a tablet; a version 1 state that
    already names ``tablet`` is not version 1's and is refused in one line."""
    from tests.states.support import frame_logs

    bare = [w for w in kas_edit if w not in ("--tablet", "emulated:summa-mm")]
    state = tmp_path / "e.c88state"
    head, parts = _saved(bare, state, "1.3")
    assert head["state_version"] == 2 and head["values"]["input"].pop("tablet") is None
    head["state_version"] = 1
    state.write_bytes(pack("program", head, parts))
    with frame_logs(monkeypatch) as runs:
        assert main([*bare, "--load-state", str(state)]) == 0
        assert main([*kas_edit, "--load-state", str(state)]) == 0  # the tablet carries on
    assert runs[0] == runs[1]  # (the script's mouse drives the emulated tablet as it would)
    head["values"]["input"]["tablet"] = None
    state.write_bytes(pack("program", head, parts))
    assert "its input log is not version 1's" in _refusal(bare, state)


ACTORS_EVENTS = "wait 5\nkey tab\nwait 3\nclick left 32 472\nwait 20\n"


def _scripted_tablet(monkeypatch, skip: int = 0) -> None:
    """``--tablet loop://?protocol=summa-mm&init=0`` as a tablet that sends a stroke, one
    report a poll, through pyserial's in-process loop: the same bytes at the same polls in
    every run (a real device's timing is the wall clock's); ``skip``: the reports it sent
    before (a loaded run's tablet goes on with the stroke where the saved one was)."""
    from camlab88.protocols.tablets import sources
    from camlab88.protocols.tablets.events import TabletEvent
    from camlab88.protocols.tablets.registry import make_encoder
    from camlab88.protocols.tablets.serial_source import SerialSource

    encoder = make_encoder("summa-mm")
    stroke = [encoder.encode(TabletEvent(1000 + 100 * i, 2000 + 50 * i, True, int(4 < i < 20)))
              for i in range(30)][skip:]

    class Scripted(SerialSource):
        def read(self, timeout: float = 0.0) -> list:
            if stroke:
                self.port.write(stroke.pop(0))
            return super().read(timeout)

    real = sources.open_source
    monkeypatch.setattr(sources, "open_source",
                        lambda spec, on_raw=None: Scripted(spec) if spec.kind == "url"
                        else real(spec, on_raw))


def test_the_actors_editor_with_a_tablet_continues_from_a_state(monkeypatch,
                                                                tmp_path: Path) -> None:
    """The Rainbow's editors (RainbowTarget.keep_input) keep a --tablet's tape the same way:
    saved mid-stroke, loaded, continued: the unbroken run's frames."""
    (tmp_path / "m.actors").write_text("rules maze\nactor 1 wall\n  colour 9 9 9\n  box 1 1 1\n"
                                       "end\n", encoding="utf-8")
    (tmp_path / "e.events").write_text(ACTORS_EVENTS)
    argv = ["ca", "actors", str(tmp_path / "m.actors"), "--headless", "--events",
            str(tmp_path / "e.events"), "--tablet", "loop://?protocol=summa-mm&init=0"]
    state = tmp_path / "a.c88state"

    def each_run(args: list[str]) -> int:  # the stroke, from where the state left it
        skip = 0
        if "--load-state" in args:
            head, parts = unpack(state.read_bytes(), "program")
            skip = parts[head["values"]["input"]["tablet"]["tape"]].count(b'"raw"')
        _scripted_tablet(monkeypatch, skip)
        return main(args)

    monkeypatch.setattr("tests.states.support.main", each_run)
    assert_continues(monkeypatch, argv, 0.3, state)
    head, parts = unpack(state.read_bytes(), "program")
    tablet = head["values"]["input"]["tablet"]
    assert (tablet["protocol"], tablet["emulated"]) == ("summa-mm", False)
    assert parts[tablet["tape"]].count(b'"raw"') >= 10


def test_a_recording_begun_from_a_tablet_state_replays_with_check(kas_edit, tmp_path: Path,
                                                                  capsys) -> None:
    """The recording carries the state by content and the tablet's tape from the load on
    (its polls counted on from the saved session's): the replay runs the state's tape, then
    the recording's, and every screen hash agrees."""
    import json

    from camlab88.protocols.session import read

    state, rec = tmp_path / "e.c88state", tmp_path / "r.rec"
    _saved(kas_edit, state)
    assert main([*kas_edit, "--load-state", str(state), "--record", str(rec)]) == 0
    polls = [e[0] for _t, d, data in read(rec).wire if d == "T" for e in json.loads(data)]
    assert polls[0] == 0 and min(polls[1:]) > 50  # its calibration; the rest after the load
    capsys.readouterr()
    assert main(["replay", str(rec), "--check"]) == 0
    assert "screen hashes agree" in capsys.readouterr().out


def test_an_actors_recording_begun_from_a_tablet_state_replays_with_check(
        monkeypatch, tmp_path: Path, capsys) -> None:
    """As for kas edit: the Rainbow's editors read the recording's tape from the polls the
    state's ran to, the tablet in as it was (not lost for want of an opening at poll 0)."""
    (tmp_path / "m.actors").write_text("rules maze\nactor 1 wall\n  colour 9 9 9\n  box 1 1 1\n"
                                       "end\n", encoding="utf-8")
    (tmp_path / "e.events").write_text(ACTORS_EVENTS)
    argv = ["ca", "actors", str(tmp_path / "m.actors"), "--headless", "--events",
            str(tmp_path / "e.events"), "--tablet", "loop://?protocol=summa-mm&init=0"]
    state, rec = tmp_path / "a.c88state", tmp_path / "r.rec"
    _scripted_tablet(monkeypatch)
    assert main([*argv, "--save-state", str(state), "--at", "0.3"]) == 0
    _scripted_tablet(monkeypatch, 15)
    assert main([*argv, "--load-state", str(state), "--record", str(rec)]) == 0
    capsys.readouterr()
    assert main(["replay", str(rec), "--check"]) == 0
    said = capsys.readouterr()
    assert "screen hashes agree" in said.out and "tablet lost" not in said.err


def test_a_state_saved_in_a_replay_keeps_the_recordings_tablet_tape(kas_edit, tmp_path: Path,
                                                                    capsys) -> None:
    """A replay reads the recording's tape, not a device: a state it saves keeps that
    tape's entries at the polls reached, and loads into a live run with the stroke."""
    rec, state = tmp_path / "r.rec", tmp_path / "x.c88state"
    assert main([*kas_edit, "--record", str(rec)]) == 0
    (tmp_path / "k.kas").unlink()
    assert main(["replay", str(rec), "--save-state", str(state), "--at", "1.2"]) == 0
    head, parts = unpack(state.read_bytes(), "program")
    assert parts[head["values"]["input"]["tablet"]["tape"]].count(b'"raw"') > 10
    capsys.readouterr()
    assert main([*kas_edit, "--load-state", str(state)]) == 0
    assert "1 chains, 3 points" in capsys.readouterr().out


def test_a_session_past_the_tape_bound_saves_no_state(monkeypatch) -> None:
    """The bound is checked before a chunk is held: past it nothing more is kept and a save
    is refused in one line (the run goes on)."""
    from camlab88.emulator.harness import input_log
    from camlab88.emulator.machine.state_file import MachineStateError

    monkeypatch.setattr(input_log, "MAX_TABLET_TAPE", 40)
    chunks = [b'[[0,"raw","0a0b0c"]]', b'[[1,"raw","0a0b0c"]]', b'[[2,"raw","0a0b0c"]]']
    log = input_log.InputLog()
    log.keep_tablet("summa-mm", False, lambda: chunks.pop(0) if chunks else b"")
    log.ticked()
    log.ticked()
    assert log.values("")["tablet"]["tape"] == b'[[0,"raw","0a0b0c"],[1,"raw","0a0b0c"]]'
    log.ticked()
    assert log.tablet.chunks == []
    with pytest.raises(MachineStateError, match="MiB a state keeps"):
        log.values("")
