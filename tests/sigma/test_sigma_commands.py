"""The commands end to end: render (raw and recorded streams), run over a pty, the demo."""

from __future__ import annotations

import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from camlab88.cli import main
from camlab88.emulator.sigma import Terminal
from camlab88.protocols.link import LineSettings, SerialLine, VirtualClock
from camlab88.protocols.link.recording import Recorder, read_recording
from camlab88.protocols.link.replay import ReplayEndpoint
from camlab88.protocols.sigma import Encoder
from tests.sigma.streams import gks_plot, pgplot_plot


def _png(path: Path) -> np.ndarray:
    with Image.open(path) as im:
        return np.asarray(im.convert("RGB"))


def test_render_raw_stream_and_frames(tmp_path: Path) -> None:
    data = pgplot_plot()
    src = tmp_path / "plot.bin"
    src.write_bytes(data)
    out = tmp_path / "plot.png"
    assert main(["sigma", "render", "--model", "t5684", "--in", str(src), "--out", str(out),
                 "--frames", str(tmp_path / "frames"), "--fps", "25"]) == 0
    t = Terminal("t5684")
    t.feed(data)
    assert np.array_equal(_png(out), t.frame())
    frames = sorted((tmp_path / "frames").glob("frame_*.png"))
    # one frame per 1/25 s: 9600 baud carries 38.4 characters per frame
    assert len(frames) == -(-len(data) * 25 // 960)
    assert np.array_equal(_png(frames[-1]), t.frame())
    t2 = Terminal("t5684")
    t2.feed(data[:int(38.4 * 3)])  # the bytes that have arrived by the end of frame 2
    assert np.array_equal(_png(frames[2]), t2.frame())


def test_render_bad_input_is_a_clear_error(tmp_path: Path) -> None:
    with pytest.raises(SystemExit, match="cannot read"):
        main(["sigma", "render", "--in", str(tmp_path / "missing"), "--out", "x.png"])
    bad = tmp_path / "bad.rec"
    bad.write_text("camlab88-link-recording 1\nline 9600 8N1\nxonxoff on\n0 > zz\n")
    with pytest.raises(SystemExit, match="bad.rec"):
        main(["sigma", "render", "--in", str(bad), "--out", str(tmp_path / "x.png")])


def _session(rec_path: Path) -> tuple[Terminal, list[np.ndarray]]:
    """A live session on a recorded line: the host draws, asks for the cursor, a key is struck."""
    settings = LineSettings()
    clock = VirtualClock()
    recorder = Recorder(rec_path, settings)
    line = SerialLine(settings, clock=clock, recorder=recorder)
    term = Terminal("t5684")
    term.on_output = line.device.write
    e = Encoder()
    line.host.write(gks_plot() + b"\r+-*/" + e.move(300, 200) + e.cursor_attach()
                    + e.cursor_on() + e.cursor_report())
    frames = []
    k = 0
    while clock.exact < Fraction(line.host.drain_time()) + 1:
        k += 1
        clock.advance_to(Fraction(k, 25))
        term.feed(line.device.read())
        frames.append(term.frame())
    term.cursor_keys(5, 5)
    term.key("Q")  # ends the cursor read: the report goes up the line
    clock.advance(Fraction(1, 10))
    reply = line.host.read()
    assert reply == b"Q305,205\r"
    line.finish()
    recorder.close()
    return term, frames


def test_record_then_replay_is_bit_identical(tmp_path: Path) -> None:
    rec = tmp_path / "session.rec"
    live, live_frames = _session(rec)
    recording = read_recording(rec)
    assert recording.stream("<") == b"Q305,205\r"
    # replay at the same read times: every frame identical
    clock = VirtualClock()
    ep = ReplayEndpoint(recording, ">", clock)
    term = Terminal("t5684")
    for k, want in enumerate(live_frames, 1):
        clock.advance_to(Fraction(k, 25))
        term.feed(ep.read())
        assert np.array_equal(term.frame(), want), f"frame {k} differs"
    # and the render command reads the recording too
    out = tmp_path / "replay.png"
    assert main(["sigma", "render", "--in", str(rec), "--out", str(out)]) == 0
    t = Terminal("t5684")
    t.feed(recording.stream(">"))
    assert np.array_equal(_png(out), t.frame())


def test_pty_end_to_end_with_pyserial(tmp_path: Path) -> None:
    serial = pytest.importorskip("serial")
    shot = tmp_path / "pty.png"
    rec = tmp_path / "pty.rec"
    proc = subprocess.Popen(
        [sys.executable, "-m", "camlab88", "sigma", "run", "--headless", "--pty",
         "--seconds", "4", "--screenshot", str(shot), "--record-line", str(rec)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        first = proc.stdout.readline()
        assert "on pty" in first, first + proc.stderr.read()
        port = serial.Serial(first.split()[-1], 9600, timeout=0.1)
        data = pgplot_plot()[:1200]  # 1.25 s of line time: arrives well before 4 s
        port.write(data)
        port.flush()
        out, err = proc.communicate(timeout=60)
        port.close()
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 0, err
    assert "1200 bytes in" in out
    t = Terminal("t5684")
    t.feed(data)
    assert np.array_equal(_png(shot), t.frame())
    assert read_recording(rec).stream(">") == data


def test_demo_headless_writes_frames_and_gif(tmp_path: Path) -> None:
    from camlab88.protocols.sigma.demo import sigma_demo_stream

    stream = sigma_demo_stream()
    t = Terminal("t5684")
    t.feed(stream)
    assert t.stats["unknown"] == t.stats["malformed"] == t.stats["errors"] == 0
    out = tmp_path / "demo"
    assert main(["demo", "--headless", "--only", "sigma", "--out", str(out)]) == 0
    pngs = sorted(out.glob("sigma_*.png"))
    assert len(pngs) == -(-len(stream) * 25 // 960)
    assert np.array_equal(_png(pngs[-1]), t.frame())
    with Image.open(out / "sigma_demo.gif") as gif:
        assert gif.n_frames > 10


def test_tcp_listen_end_to_end(tmp_path: Path) -> None:
    import socket

    shot = tmp_path / "tcp.png"
    proc = subprocess.Popen(
        [sys.executable, "-m", "camlab88", "sigma", "run", "--headless", "--listen", "0",
         "--model", "t5688", "--seconds", "3.5", "--screenshot", str(shot)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        first = proc.stdout.readline()
        assert "listening on 127.0.0.1:" in first, first + proc.stderr.read()
        port = int(first.rsplit(":", 1)[1])
        data = gks_plot(high_res=True)[:900]
        with socket.create_connection(("127.0.0.1", port), timeout=10) as sock:
            sock.sendall(data)
            out, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 0, err
    t = Terminal("t5688")
    t.feed(data)
    assert np.array_equal(_png(shot), t.frame())
