"""Commands name the files they read and wrote: a missing input is named without Python's
errno text, every file written is named in the closing line, and a command that does not
run creates no file (where each was found: docs/newcomer_trial.md). Commands run in-process
through the console script's ``main``; files go to tmp_path."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.cli import main

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def _run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    try:
        rc = main(list(argv))
    except SystemExit as exc:  # argparse and the display rule exit
        rc = exc.code if isinstance(exc.code, int) else 2
        if isinstance(exc.code, str):
            print(exc.code, file=__import__("sys").stderr)
    out, err = capsys.readouterr()
    return rc, out, err


@pytest.fixture
def in_tmp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("CAMLAB88_KAS_LIBRARY", str(tmp_path / "library"))
    return tmp_path


# -- a missing script file is named, not a raw [Errno 2] --------------------------------------

@pytest.mark.parametrize("argv", [
    ("kas", "edit-script", "session.txt", "--out", "key.kas"),
    ("kas", "path-script", "walk_a", "walk_b", "session.txt", "--path-out", "p.kas",
     "--timing-out", "t.kas"),
])
def test_a_missing_kas_script_is_named_without_errno(in_tmp: Path, capsys, argv) -> None:
    rc, out, err = _run(capsys, *argv)
    assert rc == 2
    assert "session.txt: cannot read: No such file or directory" in err
    assert "[Errno" not in err


def test_a_missing_camera_script_for_film_is_named_without_errno(in_tmp: Path, capsys) -> None:
    cp = ROOT / "tests/data/snooker_camera/pink_shot.checkpoint"
    rc, out, err = _run(capsys, "snooker", "film", str(cp), "script.ccl", "--out", "shot.mp4")
    assert rc == 2
    assert "script.ccl: no such file" in err
    assert "[Errno" not in err
    assert not (in_tmp / "shot.views").exists()  # refused before any work


# -- every command that writes files names them ----------------------------------------------

def test_path_script_names_the_path_and_timing_it_wrote(in_tmp: Path, capsys) -> None:
    kas = str(EXAMPLES / "kas")
    assert _run(capsys, "kas", "edit-script", f"{kas}/house.script", "--out", "a.kas")[0] == 0
    assert _run(capsys, "kas", "edit-script", f"{kas}/move.script", "--start", "a.kas",
                "--out", "b.kas")[0] == 0
    rc, out, _ = _run(capsys, "kas", "path-script", "a.kas", "b.kas", f"{kas}/arc.script",
                      "--path-out", "arc.kas", "--timing-out", "ticks.kas")
    assert rc == 0 and (in_tmp / "arc.kas").is_file() and (in_tmp / "ticks.kas").is_file()
    assert "arc.kas" in out and "ticks.kas" in out


def test_simulate_names_the_session_file_it_saved(in_tmp: Path, capsys) -> None:
    rc, out, _ = _run(capsys, "snooker", "simulate", "--break", "5", "--out", "b.cp",
                      "--save-session", "game.json")
    assert rc == 0 and (in_tmp / "game.json").is_file()
    assert "game.json" in out


def test_film_summary_names_the_gif_too(tmp_path: Path) -> None:
    from camlab88.commands.snooker.film import summary

    text = summary(tmp_path / "shot.mp4", tmp_path / "shot.gif", 101, "101 rendered",
                   tmp_path / "shot.views", tmp_path / "shot_frames")
    assert "shot.mp4" in text and "shot.gif" in text
    assert "shot.gif" not in summary(tmp_path / "shot.mp4", None, 3, "3 rendered",
                                     tmp_path / "shot.views", tmp_path / "shot_frames")


def test_visualise_names_the_frames_it_wrote(in_tmp: Path, capsys) -> None:
    data = ROOT / "tests/data/snooker_camera"
    assert _run(capsys, "snooker", "ccl", str(data / "thesis_example.ccl"),
                str(data / "pink_shot.checkpoint"), "--out", "ex.views")[0] == 0
    rc, out, err = _run(capsys, "snooker", "visualise", str(data / "pink_shot.checkpoint"),
                        "ex.views", "--headless", "--stop-after", "3", "--frames", "fr")
    assert rc == 0
    written = sorted((in_tmp / "fr").glob("frame_*.png"))
    assert written
    assert f"wrote {len(written)} frames to fr/frame_NNNNN.png" in err


def test_ca_program_names_the_log_it_wrote(in_tmp: Path, capsys) -> None:
    rc, out, err = _run(capsys, "ca", "program", "--headless", "--pattern", "glider",
                        "--events", str(EXAMPLES / "ca/session.events"), "--log", "s.log",
                        "--record-pans")
    assert rc == 0 and (in_tmp / "s.log").is_file()
    assert "s.log" in err


def test_kas_paint_names_first_and_last_frame(in_tmp: Path, capsys) -> None:
    assert _run(capsys, "kas", "inbetween", "sun_a", "sun_b", "--timing", "linear",
                "--frames", "4", "--out", "sun.kas")[0] == 0
    ops = in_tmp / "sun.ops"
    ops.write_text("KAS paint 1\npalette 1\ncolour 0 0 0 0\ngap 0\npainted 1\nops 0\nend\n",
                   encoding="utf-8")
    rc, out, _ = _run(capsys, "kas", "paint", "sun.kas", "--ops", str(ops), "--frames", "fr",
                      "--headless")
    assert rc == 0, out
    assert "wrote 4 frames to fr/frame_00001.png .. frame_00004.png" in out


# -- a refused or failed run leaves no file behind ------------------------------------------

@pytest.mark.parametrize("extra", [("--headless",), ("--headless", "--script", "nothere.txt")])
def test_kas_edit_creates_no_file_when_it_does_not_run(in_tmp: Path, capsys, extra) -> None:
    rc, out, err = _run(capsys, "kas", "edit", "new.kas", *extra)
    assert rc != 0
    assert not (in_tmp / "new.kas").exists(), out
    assert "created" not in out


def test_kas_edit_refused_for_no_display_creates_no_file(in_tmp: Path, capsys,
                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(name, raising=False)
    rc, out, err = _run(capsys, "kas", "edit", "new.kas")
    assert rc != 0 and "no display" in err
    assert not (in_tmp / "new.kas").exists()


def test_kas_edit_still_creates_the_file_when_it_runs(in_tmp: Path, capsys) -> None:
    script = in_tmp / "s.txt"
    script.write_text("down 0 0\ndown 1 1\nup 1 1\n", encoding="utf-8")
    rc, out, err = _run(capsys, "kas", "edit", "new.kas", "--headless", "--script", str(script))
    assert rc == 0, err
    assert (in_tmp / "new.kas").is_file()
    assert "created new.kas" in out


# -- replay names what it writes, like every other command --------------------------------------

def test_replay_names_every_file_and_directory_it_writes(in_tmp: Path, capsys) -> None:
    rc, _, err = _run(capsys, "ca", "program", "--headless", "--pattern", "glider",
                      "--events", str(EXAMPLES / "ca" / "session.events"),
                      "--record", "glider.session")
    assert rc == 0, err
    rc, _, err = _run(capsys, "replay", "glider.session", "--headless", "--frames", "frames",
                      "--screenshot", "last.png", "--inspect-out", "panels", "--video",
                      "glider.gif", "--save-state", "end.c88state")
    assert rc == 0, err
    lines = [line for line in err.splitlines() if line.startswith("camlab88 replay: ")]
    n = len(list((in_tmp / "frames").glob("frame_*.png")))
    assert n > 0
    named = "\n".join(lines)
    assert f"wrote {n} frames to {in_tmp / 'frames'}/frame_NNNNN.png" in named
    assert f"screenshot {in_tmp / 'last.png'}" in named
    assert f"inspector panels to {in_tmp / 'panels'}/frame_NNNNN.png" in named
    assert f"video {in_tmp / 'glider.gif'}" in named
    assert f"saved state {in_tmp / 'end.c88state'}" in named
    for path in ("last.png", "glider.gif", "end.c88state"):
        assert (in_tmp / path).is_file()
