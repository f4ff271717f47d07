"""The inspector in a real window (Xvfb): the window widens to show the panel beside the
screen, and the screenshot is the window's pixels."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.xvfb
def test_inspect_puts_the_panel_beside_the_screen_in_a_real_window(tmp_path: Path) -> None:
    if shutil.which("xvfb-run") is None:
        pytest.skip("xvfb-run is not installed (apt-get install xvfb; .ci/run does)")
    out = tmp_path / "window.png"
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    env.pop("SDL_VIDEODRIVER", None)
    run = subprocess.run(
        ["xvfb-run", "-a", "-s", "-screen 0 1280x800x24", sys.executable, "-m", "camlab88",
         "rainbow", "run", "--demo", "pads", "--inspect", "--stop-after", "5",
         "--screenshot", str(out)], env=env, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    img = np.asarray(Image.open(out).convert("RGB"))
    assert img.shape == (576, 768 + 384, 3)
    assert tuple(img[2, 770]) == (24, 24, 32)  # the panel's paper, right of the screen
