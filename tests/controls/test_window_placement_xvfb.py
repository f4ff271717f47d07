"""Window placement on a real X server (Xvfb, 1280x800, no window manager): the demo's
window fits the screen and is placed on it, with the inspector beside the screen and at
--scale 2 too (before this test the placement was checked only on SDL's dummy display,
which places nothing). Every geometry the X server reports while the window opens and
grows counts, not only the last."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.support.xvfb import XWindow, x_client, xvfb

ROOT = Path(__file__).resolve().parents[2]
SCREEN = (1280, 800)


def _watch(display: str, argv: list[str], log: Path, settled: int = 20) -> list[XWindow]:
    """Start camlab88 ``argv`` on ``display``; every mapped top-level window geometry seen
    until one has stood unchanged for ``settled`` looks (a 20th of a second apart)."""
    env = {**os.environ, "DISPLAY": display, "PYTHONPATH": str(ROOT)}
    env.pop("SDL_VIDEODRIVER", None)
    env.pop("SDL_VIDEO_CENTERED", None)
    with log.open("w") as err:
        proc = subprocess.Popen([sys.executable, "-m", "camlab88", *argv], env=env,
                                stdout=subprocess.DEVNULL, stderr=err)
    seen: list[XWindow] = []
    same = 0
    try:
        deadline = time.monotonic() + 300  # a first run compiles its kernels
        with x_client(display) as windows:
            while same < settled and time.monotonic() < deadline and proc.poll() is None:
                now = [w for w in windows() if w.mapped]
                if now:
                    same = same + 1 if seen and now[-1] == seen[-1] else 0
                    seen += now
                time.sleep(0.05)
        assert proc.poll() is None, log.read_text()
        assert same >= settled, f"no settled window: {seen[-5:]}"
    finally:
        proc.terminate()  # the demo holds its last act until the window closes
        proc.wait(timeout=60)
    return seen


def _on_screen(w: XWindow) -> bool:
    return w.x >= 0 and w.y >= 0 and w.x + w.width <= SCREEN[0] and \
        w.y + w.height <= SCREEN[1]


@pytest.mark.xvfb
@pytest.mark.parametrize("extra, size", [
    ([], (768, 512)),                                   # as it is, centred
    (["--inspect"], (768 + 384, 512)),                  # the panel beside it still fits
    (["--inspect", "--scale", "2"], (1280, round(512 * 1280 / 1152))),  # scaled to fit
])
def test_the_demo_window_fits_a_1280_wide_screen_and_is_on_it(
        extra: list[str], size: tuple[int, int], tmp_path: Path) -> None:
    with xvfb(*SCREEN) as display:
        seen = _watch(display, ["demo", "--only", "sigma", *extra], tmp_path / "stderr")
    off = [w for w in seen if not _on_screen(w)]
    assert off == [], f"partly off the {SCREEN} screen: {off[:3]}"
    last = seen[-1]
    assert (last.width, last.height) == size
    # centred (SDL_VIDEO_CENTERED, which emulator/window.py sets): equal margins
    assert last.x == (SCREEN[0] - size[0]) // 2 and last.y == (SCREEN[1] - size[1]) // 2
