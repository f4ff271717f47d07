"""`camlab88 demo`: every act plays through the emulated devices and writes its frames."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from PIL import Image

from camlab88.cli import main
from camlab88.commands import demo


def _png(path: Path) -> np.ndarray:
    with Image.open(path) as im:
        return np.asarray(im.convert("RGB"))


def test_kas_act_is_the_kas_session_played_over_the_line(tmp_path: Path) -> None:
    from camlab88.apps.kas.program import demo_session
    from camlab88.emulator.sigma import Terminal

    assert main(["demo", "--headless", "--only", "kas", "--out", str(tmp_path)]) == 0
    pngs = sorted(tmp_path.glob("kas_*.png"))
    session = demo_session()
    term = Terminal("t5684")
    term.feed(session.stream)
    # every byte the host sent has arrived by the last frame, and nothing was garbled
    assert np.array_equal(_png(pngs[-1]), term.frame())
    assert term.stats["unknown"] == term.stats["malformed"] == 0
    # one frame per 1/25 s of line time, at least as long as the session lasts
    assert len(pngs) >= int(session.duration * 25)
    # the editor screen (first part) differs from the viewer's last frame
    assert not np.array_equal(_png(pngs[len(pngs) // 4]), _png(pngs[-1]))
    with Image.open(tmp_path / "kas_demo.gif") as gif:
        assert gif.n_frames > 10


def test_acts_are_listed_in_help() -> None:
    names = [a.name for a in demo.ACTS]
    assert names == ["sigma", "kas", "paint", "snooker", "snooker_camera", "film", "ca", "shelf"]
    assert len(set(names)) == len(names)


def test_ca_act_plays_the_gun_on_the_rainbow(tmp_path: Path) -> None:
    assert main(["demo", "--headless", "--only", "ca", "--out", str(tmp_path)]) == 0
    pngs = sorted(tmp_path.glob("ca_*.png"))
    assert len(pngs) > 20
    first, last = _png(pngs[0]), _png(pngs[-1])
    assert first.shape == (576, 768, 3)
    # the gun has fired: the final screen differs from the first, and living cells are shown
    assert not np.array_equal(first, last)
    assert len(np.unique(last.reshape(-1, 3), axis=0)) >= 3


def test_snooker_act_replays_a_break_on_the_rainbow(tmp_path: Path) -> None:
    assert main(["demo", "--headless", "--only", "snooker", "--out", str(tmp_path)]) == 0
    pngs = sorted(tmp_path.glob("snooker_*.png"))
    assert len(pngs) >= 50  # 4 s at 25 frames a second
    first, last = _png(pngs[0]), _png(pngs[-1])
    assert first.shape == (576, 768, 3)
    assert not np.array_equal(first, last)  # the balls have moved


def test_paint_act_paints_the_walk_on_the_t5688(tmp_path: Path) -> None:
    assert main(["demo", "--headless", "--only", "paint", "--out", str(tmp_path)]) == 0
    pngs = sorted(tmp_path.glob("paint_*.png"))
    assert len(pngs) > 20
    last = _png(pngs[-1])
    assert last.shape == (512, 768, 3)
    # filled areas: many more colours than the four outline colours and the background
    assert len(np.unique(last.reshape(-1, 3), axis=0)) >= 6


def test_camera_act_plays_the_example_script_in_the_visualiser(tmp_path: Path) -> None:
    assert main(["demo", "--headless", "--only", "snooker_camera", "--out", str(tmp_path)]) == 0
    pngs = sorted(tmp_path.glob("snooker_camera_*.png"))
    assert len(pngs) >= 50
    first, last = _png(pngs[0]), _png(pngs[-1])
    assert first.shape == (576, 768, 3)
    assert not np.array_equal(first, last)  # the view and the balls move


def test_shelf_act_slides_the_unit_apart(tmp_path: Path) -> None:
    assert main(["demo", "--headless", "--only", "shelf", "--out", str(tmp_path)]) == 0
    pngs = sorted(tmp_path.glob("shelf_*.png"))
    assert len(pngs) == 100
    assert not np.array_equal(_png(pngs[0]), _png(pngs[50]))


def test_an_act_shown_through_a_callback_is_computed_no_further_than_the_frame_shown() -> None:
    """The inspector reads the act's device as the frame is shown: the program runs in
    lockstep with the frames taken (acts.lockstep), never ahead."""
    from camlab88.commands.demo.acts import Stage

    act = next(a for a in demo.ACTS if a.name == "ca")
    stage = Stage()
    for k, frame in enumerate(act.play(stage)):
        assert np.array_equal(frame, stage.machine.shown())
        if k == 30:
            break


def test_the_acts_play_in_one_run_with_the_controls_and_each_acts_inspector(
        tmp_path: Path, monkeypatch, capsys) -> None:
    import camlab88.emulator.harness as harness

    runs = []
    real = harness.run
    monkeypatch.setattr(harness, "run", lambda *a, **k: runs.append(a) or real(*a, **k))
    out, panels, video = tmp_path / "out", tmp_path / "panels", tmp_path / "demo.gif"
    assert main(["demo", "--headless", "--only", "kas", "--only", "shelf", "--out", str(out),
                 "--inspect-out", str(panels), "--video", str(video), "--speed", "1000"]) == 0
    assert len(runs) == 1  # one run, so one window, across the acts
    kas, shelf = sorted(out.glob("kas_*.png")), sorted(out.glob("shelf_*.png"))
    assert _png(kas[0]).shape == (512, 768, 3) and _png(shelf[0]).shape == (576, 768, 3)
    shown = sorted(panels.glob("frame_*.png"))
    assert len(shown) == len(kas) + len(shelf)
    # the KAS act's panel is a Sigma's, the shelf act's a Rainbow's: they differ at the top
    first_kas, first_shelf = _png(shown[0]), _png(shown[len(kas)])
    assert first_kas.shape[1] == first_shelf.shape[1]
    assert not np.array_equal(first_kas[:40], first_shelf[:40])
    assert video.is_file()
    err = capsys.readouterr().err
    assert "act 1/2" in err and "act 2/2" in err and f"video {video}" in err
