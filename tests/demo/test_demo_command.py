"""`camlab88 demo`: every act plays through the emulated devices and writes its frames."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from camlab88.cli import main
from camlab88.commands import demo
from PIL import Image


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
