"""`camlab88 snooker play [SESSION]` and `camlab88 snooker replay`, headless, and the
demo function for `camlab88 demo`."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

from camlab88.apps.snooker import checkpoint
from camlab88.apps.snooker.program import pads
from camlab88.apps.snooker.session import Session
from camlab88.apps.snooker.table import CUE
from camlab88.cli import main
from tests.snooker_program.helpers import hex_rgb, saved_game


def test_play_headless_with_events_screenshot_and_exit_save(tmp_path, capsys):
    events = tmp_path / "s.events"
    # velocity by keyboard on the cue ball, run, then Exit (green menu, up one) and save
    # time frames 1..3 of the checkpoint (the session file keeps everything)
    events.write_text(
        "move 175 325\npress middle\nglide 175 250 25\nwait 1\nrelease middle\nwait 1\n"
        "type 1 0\nkey return\nwait 1\npress right\nrelease right\nwait 10\n"
        "move 300 430\nwait 1\npress middle\nglide 300 412 6\nwait 1\nrelease middle\n"
        "wait 1\nkey y\nwait 1\ntype 1 3\nkey return\nwait 1\n")
    shot, save = tmp_path / "shot.png", tmp_path / "game.json"
    assert main(["snooker", "play", "--headless", "--events", str(events),
                 "--screenshot", str(shot), "--save", str(save)]) == 0
    out = capsys.readouterr().out
    assert "saved" in out and save.exists() and save.with_suffix(".cp").exists()
    s = Session.load(save)
    assert len(s.timeline.time_frames) == 6  # 10 display frames of running = 5 time frames
    assert s.timeline.time_frames[0].balls.vel[CUE] == pytest.approx((1.0, 0.0))
    assert checkpoint.read(save.with_suffix(".cp")).n_frames == 3
    img = np.asarray(Image.open(shot).convert("RGB"))
    assert img.shape == (576, 768, 3)
    assert (img == hex_rgb(pads.TABLE_COLOURS[pads.CLOTH])).all(axis=-1).sum() > 100_000


def test_play_restores_a_session(tmp_path, capsys):
    path = tmp_path / "g.json"
    s = saved_game(path, 0.0)
    events = tmp_path / "r.events"
    events.write_text("key r\nwait 2\n")
    assert main(["snooker", "play", str(path), "--headless", "--events", str(events)]) == 0
    assert f"({len(s.timeline.time_frames)} time frames)" in capsys.readouterr().out


def test_play_reports_bad_files(tmp_path, capsys):
    bad = tmp_path / "bad.events"
    bad.write_text("move 1 2\nfly\n")
    assert main(["snooker", "play", "--headless", "--events", str(bad)]) == 2
    assert "bad.events:2:1: unknown command 'fly'" in capsys.readouterr().err
    sess = tmp_path / "s.json"
    sess.write_text("{nope")
    assert main(["snooker", "play", str(sess), "--headless"]) == 2
    assert "s.json:1:" in capsys.readouterr().err


def test_replay_plays_a_checkpoint_at_25_fps(tmp_path, capsys):
    cp = tmp_path / "b.cp"
    assert main(["snooker", "simulate", "--break", "6", "--out", str(cp)]) == 0
    n = checkpoint.read(cp).n_frames
    shot = tmp_path / "r.png"
    assert main(["snooker", "replay", str(cp), "--headless", "--first", "0", "--last", "19",
                 "--screenshot", str(shot)]) == 0
    out = capsys.readouterr().out
    assert "20 frames at 25 frames/s (40 display frames, 0.80 s)" in out and n > 20
    assert shot.exists()
    assert main(["snooker", "replay", str(tmp_path / "missing.cp"), "--headless"]) == 2
    assert "missing.cp" in capsys.readouterr().err


def test_demo_act_replays_a_break():
    from camlab88.commands.demo.acts import ACTS

    act = next(a for a in ACTS if a.name == "snooker")
    frames = [f[300, 600].copy() for f in act.play()]
    assert len(frames) == 200  # 4 s: 100 time frames, 2 display frames each
    assert len({tuple(f) for f in frames}) > 1  # something moved


def test_replay_without_a_display_or_output_refuses_at_once_with_the_output_flags(
        tmp_path, capsys, monkeypatch):
    from camlab88.cli import entry

    cp = tmp_path / "b.cp"
    assert main(["snooker", "simulate", "--break", "6", "--out", str(cp)]) == 0
    capsys.readouterr()
    for var in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(var, raising=False)
    monkeypatch.setattr("sys.platform", "linux")
    played = []
    monkeypatch.setattr("camlab88.commands.snooker.replay._run", lambda *a: played.append(a))
    assert entry(["snooker", "replay", str(cp)]) == 2
    out, err = capsys.readouterr()
    assert played == [] and out == ""
    assert "no display for a window; give --frames DIR or --screenshot PNG" in err


def test_replay_headless_without_output_says_nothing_was_written_and_how_to(tmp_path, capsys):
    cp = tmp_path / "b.cp"
    assert main(["snooker", "simulate", "--break", "6", "--out", str(cp)]) == 0
    assert main(["snooker", "replay", str(cp), "--headless", "--last", "4"]) == 0
    out = capsys.readouterr().out
    assert "nothing was shown or written; give --frames DIR or --screenshot PNG" in out
    assert main(["snooker", "replay", str(cp), "--headless", "--last", "4",
                 "--frames", str(tmp_path / "f")]) == 0
    assert "nothing was" not in capsys.readouterr().out
    assert sorted(p.name for p in (tmp_path / "f").iterdir())[:1] == ["frame_00000.png"]
