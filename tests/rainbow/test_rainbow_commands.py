"""`camlab88 rainbow render` and `camlab88 rainbow run --headless`."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from PIL import Image

from camlab88.cli import main
from tests.support.golden import assert_matches_golden

DATA = Path(__file__).resolve().parents[1] / "data" / "rainbow"


def _png(path: Path) -> np.ndarray:
    return np.asarray(Image.open(path).convert("RGB"))


def test_render_matches_golden_and_reference(tmp_path) -> None:
    out, ref, bands = tmp_path / "a.png", tmp_path / "r.png", tmp_path / "b.txt"
    assert main(["rainbow", "render", str(DATA / "golden_scene.json"), "--out", str(out),
                 "--bands", str(bands)]) == 0
    assert main(["rainbow", "render", str(DATA / "golden_scene.json"), "--out", str(ref),
                 "--reference"]) == 0
    frame = _png(out)
    assert frame.shape == (576, 768, 3)
    assert np.array_equal(frame, _png(ref))
    assert_matches_golden(frame, DATA / "golden_scene.png")
    text = bands.read_text()
    assert text.startswith("# camlab88 Rainbow band structure v1")
    assert " concat" in text and "virtual colour=LUT[1024]" in text


def _bad(tmp_path, scene, capsys) -> str:
    p = tmp_path / "s.json"
    p.write_text(scene if isinstance(scene, str) else json.dumps(scene))
    assert main(["rainbow", "render", str(p), "--out", str(tmp_path / "o.png")]) == 2
    assert not (tmp_path / "o.png").exists()
    return capsys.readouterr().err


def test_bad_scenes_name_the_json_path(tmp_path, capsys) -> None:
    pad = {"type": "pad", "width": 4, "height": 4, "depth": 2}
    assert "$.nodes.p.depth" in _bad(tmp_path, {"nodes": {"p": {**pad, "depth": 9}}}, capsys)
    assert "$.lut[1][1]" in _bad(tmp_path, {"lut": [[0, "#000000"], [1, "red"]]}, capsys)
    assert "$.arcs[0].child" in _bad(
        tmp_path, {"nodes": {"p": pad}, "arcs": [{"parent": "screen", "child": "q"}]}, capsys)
    assert "$.nodes.p.pixels" in _bad(tmp_path, {"nodes": {"p": {**pad, "pixels": "AAAA"}}},
                                      capsys)
    assert "cycle" in _bad(tmp_path, {
        "nodes": {"a": {"type": "cluster", "width": 5, "height": 5},
                  "b": {"type": "cluster", "width": 5, "height": 5}},
        "arcs": [{"parent": "a", "child": "b"}, {"parent": "b", "child": "a"}]}, capsys)
    assert "s.json:1:" in _bad(tmp_path, "{nodes", capsys)


def test_run_headless_screenshot(tmp_path) -> None:
    shot = tmp_path / "demo.png"
    assert main(["rainbow", "run", "--headless", "--screenshot", str(shot),
                 "--screenshot-frame", "5"]) == 0
    img = _png(shot)
    assert img.shape == (576, 768, 3)
    assert (img == [255, 0, 0]).all(axis=-1).sum() > 1000  # the red polygon is there


def test_tablet_reports_become_rainbow_tablet_events() -> None:
    from camlab88.emulator.rainbow.host_input import tablet_event
    from camlab88.protocols.rainbow.events import TabletEvent
    from camlab88.protocols.tablets.events import TabletEvent as Report

    assert tablet_event(Report(1500, 900, True, 1, 2000)) == TabletEvent(0, 1500, 900, 1023, 1,
                                                                        True)
    assert tablet_event(Report(5, 6, False)) == TabletEvent(0, 5, 6, 0, 0, False)


def test_bad_tablet_source_is_a_clear_error(capsys) -> None:
    import pytest

    with pytest.raises(SystemExit, match="--tablet nonsense"):
        main(["rainbow", "run", "--headless", "--stop-after", "1", "--tablet", "nonsense"])


def test_demo_menu_by_mouse() -> None:
    from camlab88.emulator.machine import RainbowMachine
    from camlab88.protocols.rainbow.demo import MENU_ITEMS, Demo
    from camlab88.protocols.rainbow.events import MIDDLE, MouseEvent
    from camlab88.protocols.rainbow.ui.menu import ROW_H

    s = RainbowMachine()
    demo = Demo(s.client)
    demo.step()
    s.post(MouseEvent(0, 600, 200, MIDDLE, 2, True))
    demo.step()
    assert demo.menu.open_ and demo.menu.highlighted == MENU_ITEMS.index("Do nothing")
    # move up to "Faster" (two rows above 'Do nothing'), release
    s.post(MouseEvent(0, 600, 200 - 2 * ROW_H, MIDDLE))
    demo.step()
    s.post(MouseEvent(0, 600, 200 - 2 * ROW_H, 0, 2, False))
    demo.step()
    assert not demo.menu.open_ and demo.speed == 1.5
    assert demo.msg.text == "Selected: Faster"


def test_strict_memory_out_of_room_names_the_pad(tmp_path, capsys) -> None:
    scene = {"nodes": {"big": {"type": "pad", "width": 512, "height": 256, "depth": 8},
                       "more": {"type": "pad", "width": 16, "height": 16, "depth": 1}}}
    p = tmp_path / "s.json"
    p.write_text(json.dumps(scene))
    assert main(["rainbow", "render", str(p), "--out", str(tmp_path / "o.png")]) == 0
    assert main(["rainbow", "render", str(p), "--out", str(tmp_path / "o.png"),
                 "--strict"]) == 2
    err = capsys.readouterr().err
    assert "$.nodes.more" in err and "out of video memory" in err


def test_serve_command_runs_a_program_over_a_socket(tmp_path) -> None:
    import subprocess
    import sys

    from camlab88.protocols.rainbow import RainbowClient, SocketTransport

    proc = subprocess.Popen(
        [sys.executable, "-m", "camlab88", "rainbow", "serve", "--headless", "--port", "0",
         "--connections", "1"], stdout=subprocess.PIPE, text=True)
    try:
        line = proc.stdout.readline()
        port = int(line.rsplit(":", 1)[1])
        c = RainbowClient(SocketTransport(port))
        p = c.create_pad(10, 10, 1)
        c.map(0, p)
        c.line(p, 0, 0, 9, 9, 1)
        assert c.get_pixels(p, 0, 0, 3, 3).tolist() == [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
        assert c.hello()["memory_w"] == 2048
        c.close()
        assert proc.wait(timeout=20) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
        proc.stdout.close()


def test_run_record_then_replay_reproduces_the_frame(tmp_path, capsys) -> None:
    rec, a, b = tmp_path / "demo.rec", tmp_path / "a.png", tmp_path / "b.png"
    assert main(["rainbow", "run", "--headless", "--stop-after", "12", "--record-stream", str(rec),
                 "--screenshot", str(a), "--screenshot-frame", "12"]) == 0
    assert main(["rainbow", "replay", str(rec), "--headless", "--screenshot", str(b)]) == 0
    assert "0 mismatches" in capsys.readouterr().out
    assert np.array_equal(_png(a), _png(b))
    # a tampered reply is reported
    lines = rec.read_text().splitlines()
    n = next(i for i, line in enumerate(lines) if line.startswith("< ") and len(line) > 20)
    lines[n] = lines[n][:-2] + ("00" if not lines[n].endswith("00") else "01")
    rec.write_text("\n".join(lines) + "\n")
    assert main(["rainbow", "replay", str(rec), "--headless"]) == 1


def test_host_input_becomes_rainbow_events() -> None:
    from camlab88.emulator.host_input import KeyDown, PointerButton, PointerMove, Quit
    from camlab88.emulator.rainbow.host_input import host_to_rainbow_event as convert
    from camlab88.protocols.rainbow.events import KeyEvent, MouseEvent

    held = [0]
    assert convert(PointerButton(3, 4, 2, True), held) == MouseEvent(0, 3, 4, 2, 2, True)
    assert convert(PointerMove(5, 6, frozenset({2, 3})), held) == MouseEvent(0, 5, 6, 6)
    assert convert(PointerButton(5, 6, 3, False), held) == MouseEvent(0, 5, 6, 2, 3, False)
    assert convert(KeyDown("a", "a"), held) == KeyEvent(0, "a", "a", True)
    assert convert(Quit(), held) is None
