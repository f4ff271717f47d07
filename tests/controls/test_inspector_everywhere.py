"""The inspector on every program, not only sigma run and the Rainbow's: the KAS fronts on
the T5684 (`kas edit ... --inspect-out D` was refused, "this program's device has no
inspector"), and so a replay of their recordings (`replay fig-3.1.session --inspect-out D`
failed)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from PIL import Image

from camlab88.cli import main

ROOT = Path(__file__).resolve().parents[2]


def _panels(directory: Path) -> list[np.ndarray]:
    out = []
    for p in sorted(directory.glob("frame_*.png")):
        with Image.open(p) as im:
            out.append(np.asarray(im.convert("RGB")))
    return out


def test_kas_edit_writes_its_sigmas_panels(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("CAMLAB88_KAS_LIBRARY", str(tmp_path / "library"))
    script = ROOT / "examples" / "kas" / "house.script"
    assert main(["kas", "edit", "key.kas", "--script", str(script), "--headless",
                 "--inspect-out", "panels"]) == 0
    panels = _panels(tmp_path / "panels")
    assert len(panels) > 10
    assert panels[0].shape == (512, 384, 3)
    assert not np.array_equal(panels[0], panels[-1])  # the orders and planes moved on


def test_a_replay_of_a_kas_figure_writes_its_panels(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    session = ROOT / "examples" / "figures" / "fig-3.1.session"
    assert main(["replay", str(session), "--headless", "--inspect-out", "panels"]) == 0
    assert len(_panels(tmp_path / "panels")) > 10
