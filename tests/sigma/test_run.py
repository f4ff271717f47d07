"""`camlab88 sigma run` with a (dummy-driver) window: host input reaches the terminal."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
from PIL import Image

from camlab88.emulator.host_input import KeyDown, PointerButton, PointerMove
from camlab88.emulator.sigma import Terminal
from camlab88.emulator.sigma.host_input import to_terminal
from camlab88.protocols.sigma import Encoder


def _feed(events: list, term: Terminal) -> None:
    for ev in events:
        to_terminal(ev, term)


def test_window_input_goes_to_keyboard_cursor_and_tablet() -> None:
    t = Terminal("t5684")
    sent: list[bytes] = []
    t.on_output = sent.append
    arrows = [KeyDown("right", "", frozenset({"shift"})), KeyDown("up", "", frozenset())]
    _feed([KeyDown("a", "a", frozenset()), KeyDown("return", "", frozenset()), *arrows], t)
    # no cursor read armed: the cursor keys send their codes (the KAS programs' pan keys)
    assert sent == [b"a", b"\r", b"\x06", b"\x10"]
    assert (t.reg.cursor_x, t.reg.cursor_y) == (0, 0)
    t.feed(b"\r+-*/HF")  # a cursor read on the keys (CF, the default): they move the crosshair
    _feed(arrows, t)
    assert (t.reg.cursor_x, t.reg.cursor_y) == (8, 1) and len(sent) == 4
    _feed([KeyDown("q", "q", frozenset())], t)
    assert sent[-1] == b"q008,001\r"
    t.feed(b"GM3HF")
    _feed([PointerMove(100, 11, frozenset()), PointerButton(100, 11, 1, True)], t)
    assert sent[-1] == b"1100,500\r"  # window row 11 is device y 500


def test_run_with_a_window_takes_a_screenshot(tmp_path: Path) -> None:
    e = Encoder()
    stream = b"\r+-*/" + e.colour(2) + e.abbreviated_polyline([(10, 10), (700, 400)]) \
        + e.move(300, 300) + e.ellipse(40, 1.0, True)
    src = tmp_path / "s.bin"
    src.write_bytes(stream)
    shot = tmp_path / "shot.png"
    done = subprocess.run([sys.executable, "-m", "camlab88", "sigma", "run", "--in", str(src),
                           "--screenshot", str(shot), "--scale", "1"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    t = Terminal("t5684")
    t.feed(stream)
    with Image.open(shot) as im:
        assert np.array_equal(np.asarray(im.convert("RGB")), t.frame())
