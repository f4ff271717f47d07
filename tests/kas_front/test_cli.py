"""``camlab88 kas edit|path|view|export`` headless, end to end."""

from __future__ import annotations

import numpy as np
from PIL import Image

from apps.kas import files
from camlab88.cli import main
from tests.kas_front.helpers import DATA, model_only


def test_edit_headless_saves_and_screenshots(tmp_path, capsys) -> None:  # noqa: ANN001
    key, shot = tmp_path / "k.kas", tmp_path / "shot.png"
    assert main(["kas", "edit", str(key), "--script", str(DATA / "edit_all.txt"),
                 "--headless", "--seed", "1", "--screenshot", str(shot)]) == 0
    out = capsys.readouterr().out
    assert "saved" in out and "characters to the Sigma" in out
    got = files.load_keyframe(key)
    want = model_only("edit_all.txt").drawing
    assert [len(c) for c in got.chains] == [len(c) for c in want.chains]
    img = np.asarray(Image.open(shot))
    assert img.shape == (512, 768, 3) and img.any()
    # editing it again starts from the saved file
    assert main(["kas", "edit", str(key), "--script", str(DATA / "white.txt"), "--headless",
                 "--background", "white"]) == 0
    assert "7 chains" in capsys.readouterr().out


def test_edit_errors(tmp_path, capsys) -> None:  # noqa: ANN001
    assert main(["kas", "edit", str(tmp_path / "k.kas"), "--headless"]) == 2
    assert "--headless needs --script" in capsys.readouterr().err
    bad = tmp_path / "bad.txt"
    bad.write_text("move 0 0\nfly 1 2\n")
    assert main(["kas", "edit", str(tmp_path / "k.kas"), "--script", str(bad),
                 "--headless"]) == 2
    assert "bad.txt:2:" in capsys.readouterr().err


def test_path_headless(tmp_path, capsys) -> None:  # noqa: ANN001
    p = tmp_path / "p.kas"
    assert main(["kas", "path", "walk_a", "walk_b", "--out", str(p), "--script",
                 str(DATA / "path.txt"), "--headless"]) == 0
    assert len(files.load_path(p).points) == 6
    assert len(files.load_timing(tmp_path / "p_ticks.kas").values) == 4
    assert "4 ticks" in capsys.readouterr().out


def test_view_headless_counts_and_frames(tmp_path, capsys) -> None:  # noqa: ANN001
    seq = tmp_path / "d.kas"
    assert main(["kas", "demo", "--out", str(seq)]) == 0
    capsys.readouterr()
    assert main(["kas", "view", str(seq), "--headless", "--realtime"]) == 0
    slow = capsys.readouterr().out
    assert main(["kas", "view", str(seq), "--headless", "--baud", "38400", "--frames",
                 str(tmp_path / "f")]) == 0
    fast = capsys.readouterr().out
    n_slow = int(slow.split(": ")[1].split()[0])
    n_fast = int(fast.split(": ")[1].split()[0])
    assert n_slow < n_fast
    assert len(list((tmp_path / "f").glob("frame_*.png"))) >= 25
    assert main(["kas", "view", str(seq), "--headless", "--every", "--swap", "mask"]) == 0
    assert "28 shown, 0 dropped" in capsys.readouterr().out


def test_export_through_the_sigma(tmp_path, capsys) -> None:  # noqa: ANN001
    seq = tmp_path / "d.kas"
    assert main(["kas", "demo", "--out", str(seq)]) == 0
    assert main(["kas", "export", str(seq), str(tmp_path / "o.png")]) == 0
    assert "sigma renderer" in capsys.readouterr().out
    img = np.asarray(Image.open(tmp_path / "o_0001.png"))
    assert img.shape == (512, 768, 3) and img.any()
    assert len(list(tmp_path.glob("o_*.png"))) == 28


def test_edit_in_a_window_dummy_driver(tmp_path, capsys) -> None:  # noqa: ANN001
    """The windowed loop (SDL dummy driver): script events and the window's input together."""
    shot = tmp_path / "w.png"
    assert main(["kas", "edit", str(tmp_path / "k.kas"), "--script",
                 str(DATA / "white.txt"), "--screenshot", str(shot)]) == 0
    assert "screenshot" in capsys.readouterr().out
    img = np.asarray(Image.open(shot).convert("RGB"))
    assert img.shape == (512, 768, 3) and img.any()
    assert main(["kas", "view", "walk_ticks", "--screenshot", str(shot)]) == 2  # not a sequence
