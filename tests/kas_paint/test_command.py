"""``camlab88 kas paint`` headless, end to end: a scripted session saving its operations
file, then the whole sequence painted from it into frame_NNNNN.png (from 1) and a GIF."""

from __future__ import annotations

import numpy as np
from PIL import Image

from apps.kas import files
from apps.kas.paint import opsfile
from camlab88.cli import main
from tests.kas_paint.helpers import walk


def test_paint_session_then_every_frame(tmp_path, capsys) -> None:  # noqa: ANN001
    seq = walk(6)
    seq_path, ops_path = tmp_path / "w.kas", tmp_path / "w.ops"
    files.save_sequence(seq_path, seq)
    mid = seq.frames[2]  # the default painted frame of 6: frame 3
    ring, wander = mid.chains[1].points[0], mid.chains[0].points[5]
    script = tmp_path / "s.txt"
    script.write_text(f"colour 3\nselect {ring[0]} {ring[1]}\nfill\n"
                      f"colour 5\nselect {wander[0]} {wander[1]}\nfill\n")
    assert main(["kas", "paint", str(seq_path), "--script", str(script), "--headless",
                 "--save", str(ops_path)]) == 0
    assert "saved" in capsys.readouterr().out
    ops = opsfile.load(ops_path)
    assert [(o.chains, o.colour) for o in ops.ops] == [((2,), 3), ((1,), 5)]
    out = tmp_path / "frames"
    gif = tmp_path / "w.gif"
    assert main(["kas", "paint", str(seq_path), "--ops", str(ops_path), "--frames", str(out),
                 "--gif", str(gif), "--headless"]) == 0
    text = capsys.readouterr().out
    assert "6 frames painted" in text and gif.exists()
    names = sorted(p.name for p in out.iterdir())
    assert names == [f"frame_{i:05d}.png" for i in range(1, 7)]
    img = np.asarray(Image.open(out / "frame_00003.png"))
    assert img.shape == (512, 768, 3) and (img == (250, 220, 40)).all(axis=-1).sum() > 100


def test_paint_errors(tmp_path, capsys) -> None:  # noqa: ANN001
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
