"""Command-line failures are one-line errors (exit 1) naming the port or path; outputs are
world-readable; a recording given to ``run --in`` plays at its recorded times."""

from __future__ import annotations

import os
import socket
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from camlab88.cli import main
from camlab88.emulator.sigma import Terminal
from camlab88.protocols.link import LineSettings, SerialLine, VirtualClock
from camlab88.protocols.link.recording import Recorder
from camlab88.protocols.sigma import Encoder


def _fails(argv: list[str], *needles: str, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exc:
        main(argv)
    msg = str(exc.value.code)
    assert exc.value.code not in (0, None), msg
    assert "\n" not in msg.strip()
    for n in needles:
        assert n in msg, msg
    assert "bytes in" not in capsys.readouterr().out


def test_serial_url_that_cannot_open_is_an_error(capsys: pytest.CaptureFixture[str]) -> None:
    _fails(["sigma", "run", "--headless", "--serial", "/dev/camlab88-no-such-port",
            "--seconds", "0.1"], "/dev/camlab88-no-such-port", capsys=capsys)


def test_listen_on_a_port_in_use_is_an_error(capsys: pytest.CaptureFixture[str]) -> None:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen(1)
        port = s.getsockname()[1]
        _fails(["sigma", "run", "--headless", "--listen", str(port), "--seconds", "0.1"],
               f"127.0.0.1:{port}", capsys=capsys)


def test_unwritable_paths_are_errors(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    src = tmp_path / "s.bin"
    src.write_bytes(b"\r+-*/DA")
    _fails(["sigma", "render", "--in", str(src), "--out", "/proc/nope/x.png"],
           "/proc/nope/x.png", capsys=capsys)
    _fails(["sigma", "render", "--in", str(src), "--frames", "/proc/nope/frames"],
           "/proc/nope/frames", capsys=capsys)
    _fails(["sigma", "run", "--headless", "--record", "/proc/nope/x.rec", "--seconds", "0.1"],
           "/proc/nope/x.rec", capsys=capsys)
    _fails(["sigma", "run", "--headless", "--in", str(src), "--screenshot", "/proc/nope/s.png"],
           "/proc/nope/s.png", capsys=capsys)


def test_render_rejects_baud_zero(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    src = tmp_path / "s.bin"
    src.write_bytes(b"\r+-*/DA")
    _fails(["sigma", "render", "--in", str(src), "--out", str(tmp_path / "x.png"), "--baud",
            "0"], "baud", capsys=capsys)
    assert not (tmp_path / "x.png").exists()


def test_png_output_is_not_private(tmp_path: Path) -> None:
    src = tmp_path / "s.bin"
    src.write_bytes(b"\r+-*/DA")
    old = os.umask(0o022)
    try:
        assert main(["sigma", "render", "--in", str(src), "--out", str(tmp_path / "x.png")]) == 0
    finally:
        os.umask(old)
    assert (tmp_path / "x.png").stat().st_mode & 0o777 == 0o644


def test_run_replays_a_recording_at_its_recorded_times(tmp_path: Path) -> None:
    e = Encoder()
    first = b"\r+-*/" + e.colour(2) + e.polyline([(10, 10), (300, 10)])
    second = e.colour(3) + e.polyline([(10, 400), (300, 400)])
    settings = LineSettings()
    clock = VirtualClock()
    rec = tmp_path / "gap.rec"
    recorder = Recorder(rec, settings)
    line = SerialLine(settings, clock=clock, recorder=recorder)
    line.host.write(first)
    clock.advance_to(Fraction(3))  # three seconds of silence, then the second line
    line.host.write(second)
    clock.advance_to(Fraction(4))
    line.device.read()
    line.finish()
    recorder.close()
    shot = tmp_path / "at1s.png"
    assert main(["sigma", "run", "--headless", "--in", str(rec), "--seconds", "1",
                 "--screenshot", str(shot)]) == 0
    want = Terminal("t5684")
    want.feed(first)  # at 1 s only the first line has arrived
    with Image.open(shot) as im:
        assert np.array_equal(np.asarray(im.convert("RGB")), want.frame())
    shot2 = tmp_path / "at4s.png"
    assert main(["sigma", "run", "--headless", "--in", str(rec), "--seconds", "4",
                 "--screenshot", str(shot2)]) == 0
    want.feed(second)
    with Image.open(shot2) as im:
        assert np.array_equal(np.asarray(im.convert("RGB")), want.frame())
