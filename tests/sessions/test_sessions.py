"""Session recordings: the shipped ones replay bit-identically (``replay --check``); a
program whose output changes is caught at the first differing frame; window input is
recorded and replayed; damaged recordings are refused cleanly."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.protocols.session import read

DATA = Path(__file__).resolve().parents[1] / "data" / "sessions"
SHIPPED = sorted(p.name for p in DATA.glob("*.session"))


def test_at_least_a_kas_a_snooker_and_a_ca_recording_are_shipped() -> None:
    kinds = {read(DATA / name).argv[0] for name in SHIPPED}
    assert {"kas", "snooker", "ca"} <= kinds


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_recording_replays_with_check(name: str, capsys) -> None:
    assert main(["replay", str(DATA / name), "--check", "--headless"]) == 0
    out = capsys.readouterr().out
    n = len(read(DATA / name).hashes) + 1
    assert f"all {n} screen hashes agree" in out


def test_a_changed_program_fails_naming_the_first_differing_frame(monkeypatch,
                                                                   capsys) -> None:
    from camlab88.apps.ca.program.program import CAProgram

    idle = CAProgram._idle
    calls = [0]

    def lose_one_generation(self) -> None:
        calls[0] += 1
        if calls[0] != 45:  # the 45th frame of the session does no work
            idle(self)

    monkeypatch.setattr(CAProgram, "_idle", lose_one_generation)
    assert main(["replay", str(DATA / "ca_program.session"), "--check", "--headless"]) == 1
    err = capsys.readouterr().err
    m = re.search(r"frame (\d+) \(tick (\d+), t = ([\d.]+) s\) differs from the recording", err)
    assert m, err
    assert int(m[1]) == 50  # the first hash after the change (hashes every 10 frames)
    assert float(m[3]) == pytest.approx(int(m[2]) / 50)


def test_window_input_is_recorded_and_replayed(tmp_path: Path, monkeypatch,
                                               capsys) -> None:
    from camlab88.emulator.host_input import PointerButton, PointerMove, Quit
    from camlab88.emulator.window import Window

    script = {5: [PointerMove(300, 300, frozenset())],
              8: [PointerButton(300, 300, 2, True)],
              12: [PointerMove(310, 330, frozenset({2}))],
              16: [PointerButton(310, 330, 2, False)], 40: [Quit()]}
    polls = [0]

    def poll(self) -> list:
        polls[0] += 1
        return script.get(polls[0], [])

    monkeypatch.setattr(Window, "poll", poll)
    rec = tmp_path / "s.session"
    monkeypatch.chdir(tmp_path)
    # --screenshot: unpaced, so the test never sleeps
    assert main(["snooker", "play", "--record", str(rec), "--stop-after", "60",
                 "--screenshot", str(tmp_path / "w.png")]) == 0
    got = read(rec)
    assert [obj["kind"] for _t, _v, obj in got.events] == [
        "PointerMove", "PointerButton", "PointerMove", "PointerButton", "Quit"]
    monkeypatch.undo()
    capsys.readouterr()
    assert main(["replay", str(rec), "--check", "--headless"]) == 0
    assert "screen hashes agree" in capsys.readouterr().out


def test_record_then_replay_writes_frames_and_screenshot(tmp_path: Path, monkeypatch,
                                                         capsys) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "e.events").write_text("move 300 300\nwait 3\nkey r\nwait 4\n")
    assert main(["ca", "program", "--headless", "--events", "e.events", "--record",
                 "c.session"]) == 0
    (tmp_path / "e.events").write_text("garbage that would not parse\n")  # edited later
    assert main(["replay", "c.session", "--check", "--headless", "--frames", "out",
                 "--screenshot", "last.png"]) == 0
    frames = sorted((tmp_path / "out").glob("frame_*.png"))
    assert [f.name for f in frames][:2] == ["frame_00000.png", "frame_00001.png"]
    assert len(frames) == read(tmp_path / "c.session").end.frame
    assert (tmp_path / "last.png").exists()
    assert "e.events" in read(tmp_path / "c.session").files  # the input, by content


def test_unreadable_recordings_are_refused(tmp_path: Path, capsys) -> None:
    good = (DATA / "sigma_run.session").read_bytes()
    cases = {
        "truncated": (good[: len(good) // 2].rsplit(b"\n", 1)[0] + b"\n", "truncated"),
        "newer": (good.replace(b'"version":1', b'"version":7', 1), "newer camlab88"),
        "garbage": (b"hello\n", ":1:1: not JSON"),
        "empty": (b"", "empty"),
    }
    for name, (data, message) in cases.items():
        path = tmp_path / f"{name}.session"
        path.write_bytes(data)
        assert main(["replay", str(path), "--check", "--headless"]) == 2
        err = capsys.readouterr().err
        assert f"{path}:" in err and message in err, (name, err)
    assert main(["replay", str(tmp_path / "missing.session")]) == 2
    assert "cannot read" in capsys.readouterr().err


def test_a_replay_never_writes_outside_its_scratch_directory(tmp_path: Path, monkeypatch,
                                                             capsys) -> None:
    script = Path(__file__).resolve().parents[1] / "data" / "kas_front" / "path.txt"
    lib, out = tmp_path / "lib", tmp_path / "elsewhere" / "p.kas"
    out.parent.mkdir()
    monkeypatch.setenv("CAMLAB88_KAS_LIBRARY", str(lib))
    rec = tmp_path / "p.session"
    assert main(["kas", "path", "walk_a", "walk_b", "--out", str(out), "--script", str(script),
                 "--headless", "--record", str(rec)]) == 0
    assert out.exists() and any(lib.iterdir())  # the run saved the path and kept it
    out.unlink()
    before = sorted(p.name for p in lib.iterdir())
    for p in lib.iterdir():
        p.write_text("the user's own\n")
    assert main(["replay", str(rec), "--check", "--headless"]) == 0
    assert not out.exists()  # the absolute --out went into the scratch directory
    assert sorted(p.name for p in lib.iterdir()) == before
    assert all(p.read_text() == "the user's own\n" for p in lib.iterdir())
