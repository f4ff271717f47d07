"""``camlab88 kas paint`` headless, end to end: a scripted session saving its operations
file, then the whole sequence painted from it into frame_NNNNN.png (from 1) and a GIF."""

from __future__ import annotations

import numpy as np
from PIL import Image

from camlab88.apps.kas import files
from camlab88.apps.kas.paint import opsfile
from camlab88.cli import main
from tests.kas_paint.helpers import walk


def test_paint_session_then_every_frame(tmp_path, capsys) -> None:
    seq = walk(6)
    seq_path, ops_path = tmp_path / "w.kas", tmp_path / "w.ops"
    files.save_sequence(seq_path, seq)
    mid = seq.frames[2]  # the default painted frame of 6: frame 3
    ring, wander = mid.chains[1].points[0], mid.chains[0].points[5]
    script = tmp_path / "s.txt"
    script.write_text(f"colour 3\nselect {ring[0]} {ring[1]}\nfill\n"
                      f"colour 5\nselect {wander[0]} {wander[1]}\nfill\nautopaint\n")
    assert main(["kas", "paint", str(seq_path), "--script", str(script), "--headless",
                 "--save", str(ops_path)]) == 0
    assert "saved" in capsys.readouterr().out
    ops = opsfile.load(ops_path)
    assert [(o.chains, o.colour) for o in ops.ops] == [((2,), 3), ((1,), 5)]
    # auto-paint kept every other frame's seed points in the file (§3.3)
    assert sorted(ops.frame_seeds) == [1, 2, 4, 5, 6]
    ops_path.write_text(ops_path.read_text().split("frame 1 ops")[0] + "end\n")
    again = tmp_path / "again.ops"
    out = tmp_path / "frames"
    gif = tmp_path / "w.gif"
    assert main(["kas", "paint", str(seq_path), "--ops", str(ops_path), "--frames", str(out),
                 "--gif", str(gif), "--headless", "--save", str(again)]) == 0
    text = capsys.readouterr().out
    assert "6 frames painted" in text and gif.exists()
    assert opsfile.load(again).frame_seeds == ops.frame_seeds  # recomputed the same
    names = sorted(p.name for p in out.iterdir())
    assert names == [f"frame_{i:05d}.png" for i in range(1, 7)]
    img = np.asarray(Image.open(out / "frame_00003.png"))
    assert img.shape == (512, 768, 3) and (img == (250, 220, 40)).all(axis=-1).sum() > 100


def test_paint_errors(tmp_path, capsys) -> None:
    seq_path = tmp_path / "w.kas"
    files.save_sequence(seq_path, walk(3))
    bad = tmp_path / "bad.ops"
    bad.write_text("KAS paint 1\npalette 1\ncolour 0 0 0 0\ngap 0\npainted 1\nops 1\n"
                   "fill 9 colour 0\nend\n")
    assert main(["kas", "paint", str(seq_path), "--ops", str(bad), "--headless",
                 "--replay"]) == 2
    assert f"{bad}:7:6: line-chain 9 does not exist" in capsys.readouterr().err
    assert main(["kas", "paint", str(seq_path), "--headless"]) == 2
    assert "--script" in capsys.readouterr().err


def test_window_input_selects_fills_and_picks() -> None:
    """The window's mouse and keys drive the same session: click near a chain, f to fill;
    in the preview a click on a swatch picks it and r steps its red."""
    from camlab88.apps.kas.paint import areas, mixing
    from camlab88.apps.kas.paint.host import PaintHost
    from camlab88.apps.kas.paint.ops import OpsFile
    from camlab88.apps.kas.paint.session import PaintSession
    from camlab88.emulator.harness.sigma_host import SigmaHostTarget
    from camlab88.emulator.host_input import KeyDown, PointerButton
    from camlab88.emulator.machine import SigmaMachine

    seq = walk(4)
    s = PaintSession(seq, OpsFile(painted=2))
    machine = SigmaMachine("t5688", xonxoff=False)
    t = SigmaHostTarget(machine, PaintHost(s, machine.host, [], end=False), "paint", "")
    px = areas.to_px(seq.frames[1].chains[1].points[:1])[0]   # painting area = screen (KQ1)
    t.handle_events([PointerButton(int(px[0]), 511 - int(px[1]), 1, True), KeyDown("f", "f")])
    assert [(o.kind, o.chains, o.colour) for o in s.ops.ops] == [("fill", (2,), 1)]
    t.handle_events([KeyDown("p", "p")])
    x0, y0, x1, y1 = mixing.swatch_box(6)
    # preview: the drawing area at half size
    t.handle_events([PointerButton((x0 + x1) // 4, 511 - (y0 + y1) // 4, 1, True),
                     KeyDown("r", "r")])
    assert s.program.current == 6 and s.ops.palette[6][0] == min(40 + 8, 255)
    for _ in range(200):
        t.tick()
    assert machine.terminal.reg.view == 4


def test_readme_commands_as_printed(tmp_path, capsys, monkeypatch) -> None:
    """The README's painting commands, in order, with the shipped script."""
    from pathlib import Path

    script = Path(__file__).resolve().parents[1] / "data" / "kas_paint" / "walk_paint.txt"
    monkeypatch.chdir(tmp_path)
    assert main(["kas", "inbetween", "walk_a", "walk_b", "--path", "walk_path", "--timing",
                 "walk_ticks", "--out", "walk.kas"]) == 0
    assert main(["kas", "paint", "walk.kas", "--script", str(script), "--save", "walk.ops",
                 "--headless"]) == 0
    assert "0 operation(s) could not apply" in capsys.readouterr().out
    ops = opsfile.load("walk.ops")
    assert [(o.kind, o.chains, o.colour) for o in ops.ops] == [
        ("fill", (2,), 3), ("fill", (1,), 5), ("line", (1,), 8)]
    assert sorted(ops.frame_seeds) == [n for n in range(1, 21) if n != ops.painted]
    assert main(["kas", "paint", "walk.kas", "--ops", "walk.ops", "--frames", "out", "--gif",
                 "walk.gif", "--headless"]) == 0
    assert sorted(p.name for p in (tmp_path / "out").iterdir())[::19] == [
        "frame_00001.png", "frame_00020.png"]


def test_headless_replay_says_it_painted_flat_out_not_at_line_speed(
        tmp_path, capsys, monkeypatch) -> None:
    seq_path, ops = tmp_path / "w.kas", tmp_path / "w.ops"
    files.save_sequence(seq_path, walk(3))
    ops.write_text("KAS paint 1\npalette 1\ncolour 0 0 0 0\ngap 0\npainted 1\nops 0\nend\n")
    for var in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(var, raising=False)
    monkeypatch.setattr("sys.platform", "linux")
    assert main(["kas", "paint", str(seq_path), "--ops", str(ops), "--replay"]) == 0
    out, err = capsys.readouterr()
    assert "running headless (painting every frame flat out, not at the line's speed" in err
    line = next(s for s in out.splitlines() if "frames painted" in s)
    assert "s of line time at 9600 baud; headless: painted in " in line
    assert line.endswith("s, flat out, not at the line's speed")
