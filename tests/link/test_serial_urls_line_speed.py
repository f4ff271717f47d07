"""Every pyserial URL keeps up with the 9600-baud line, end to end through ``sigma run``.

A real PGPLOT stream (tests/data/link/pgplot_goctest.goc, 7,670 bytes = 7.99 s at 960
characters a second) arrives over ``socket://`` from a TCP server, over ``rfc2217://`` from
pyserial's own RFC 2217 server side (``PortManager`` in front of ``loop://``: it cannot serve
a pty, docs/link.md), and over a socat null modem; ``sigma run`` (paced: its line
time follows the wall clock the bytes arrive on) must show the whole picture by the line time
the stream needs, identical to ``sigma render`` of the same bytes.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from camlab88.protocols.link import serial_port
from tests.support.processes import child
from tests.support.serial_servers import Rfc2217Server, StreamServer, null_modem

STREAM = Path(__file__).parents[1] / "data" / "link" / "pgplot_goctest.goc"
# 7670 / 960 = 7.99 s of line time, plus the time the far end needs to start sending
LINE_SECONDS = "8.4"


def _png(path: Path) -> np.ndarray:
    with Image.open(path) as im:
        return np.asarray(im.convert("RGB"))


def _rendered(tmp_path: Path) -> np.ndarray:
    out = tmp_path / "render.png"
    subprocess.run([sys.executable, "-m", "camlab88", "sigma", "render", "--in", str(STREAM),
                    "--out", str(out)], check=True, capture_output=True, timeout=120)
    return _png(out)


def _sigma_run(url: str, shot: Path, started=None) -> str:
    with child([sys.executable, "-m", "camlab88", "sigma", "run", "--headless", "--serial", url,
                "--seconds", LINE_SECONDS, "--screenshot", str(shot)]) as proc:
        if started is not None:
            first = proc.stdout.readline()
            assert "on serial port" in first, first + proc.stderr.read()
            started()
        out, err = proc.communicate(timeout=120)
    assert proc.returncode == 0, err
    return out


def _check(out: str, shot: Path, tmp_path: Path) -> None:
    data = STREAM.read_bytes()
    assert f"{len(data)} bytes in" in out, out
    assert np.array_equal(_png(shot), _rendered(tmp_path))


def test_socket_url_carries_a_pgplot_stream_at_line_speed(tmp_path: Path) -> None:
    with StreamServer(STREAM.read_bytes()) as server:
        shot = tmp_path / "socket.png"
        out = _sigma_run(f"socket://127.0.0.1:{server.port}", shot)
    _check(out, shot, tmp_path)


def test_rfc2217_url_carries_a_pgplot_stream_at_line_speed(tmp_path: Path) -> None:
    with Rfc2217Server(STREAM.read_bytes()) as server:
        shot = tmp_path / "rfc2217.png"
        out = _sigma_run(f"rfc2217://127.0.0.1:{server.port}", shot)
    _check(out, shot, tmp_path)


def test_socat_null_modem_carries_a_pgplot_stream_at_line_speed(tmp_path: Path) -> None:
    import serial

    with null_modem(tmp_path) as ends:
        if isinstance(ends, str):
            pytest.skip(ends)
        a, b = ends
        far = serial.Serial(b, 9600, timeout=1)
        try:
            shot = tmp_path / "null_modem.png"
            out = _sigma_run(a, shot, started=lambda: far.write(STREAM.read_bytes()))
        finally:
            far.close()
    _check(out, shot, tmp_path)


def test_read_available_takes_everything_a_socket_has_not_what_in_waiting_says() -> None:

    data = STREAM.read_bytes()[:3000]
    with StreamServer(data) as server:
        port = serial_port.open_url(f"socket://127.0.0.1:{server.port}", write_timeout=2)
        try:
            assert port.in_waiting in (0, 1)  # the handler only says "readable"
            got = b""
            for _ in range(50):
                got += serial_port.read_available(port, 0.1)
                if len(got) >= len(data):
                    break
            assert got == data
            assert len(got) > 50  # not one byte a poll
        finally:
            port.close()


def test_rfc2217_opens_without_the_write_timeout_its_handler_refuses() -> None:
    import warnings

    with Rfc2217Server(b"hello") as server, warnings.catch_warnings():
        # pyserial 3.5's rfc2217 client starts its reader with the deprecated setDaemon()
        warnings.simplefilter("ignore", DeprecationWarning)
        port = serial_port.open_url(f"rfc2217://127.0.0.1:{server.port}", write_timeout=2,
                                    baudrate=9600)
        try:
            assert port.write_timeout is None
            got = b""
            for _ in range(200):
                got += serial_port.read_available(port, 0.05)
                if got:
                    break
            assert got == b"hello"
        finally:
            port.close()


def test_loop_url_reads_whole_chunks() -> None:
    port = serial_port.open_url("loop://", write_timeout=2)
    try:
        port.write(b"x" * 1000)
        assert serial_port.read_available(port, 0.5) == b"x" * 1000
        assert serial_port.read_available(port, 0.0) == b""
    finally:
        port.close()


def test_spy_url_on_a_pty_reads_whole_chunks(capsys: pytest.CaptureFixture[str]) -> None:
    from camlab88.protocols.link.pty import PtyPort

    pty = PtyPort()
    port = serial_port.open_url(f"spy://{pty.slave_path}", write_timeout=2)  # logs to stderr
    try:
        pty.write(b"y" * 1000)
        got = b""
        for _ in range(20):
            got += serial_port.read_available(port, 0.1)
            if len(got) >= 1000:
                break
        assert got == b"y" * 1000
        assert "RX" in capsys.readouterr().err  # it really went through the spy
    finally:
        port.close()
        pty.close()


def test_a_serial_tablet_over_socket_url_reads_whole_bursts() -> None:
    """The tablet path shares the rule: a burst of Bit Pad One reports over socket:// is
    decoded in a few reads, not one byte a read."""
    from camlab88.protocols.tablets.events import TabletEvent
    from camlab88.protocols.tablets.registry import make_encoder
    from camlab88.protocols.tablets.sources import open_source

    encode = make_encoder("bitpad1").encode
    burst = b"".join(encode(TabletEvent(100 + k, 200, True, 1)) for k in range(200))
    with StreamServer(burst) as server:
        source = open_source(f"socket://127.0.0.1:{server.port}?protocol=bitpad1")
        try:
            events = []
            for _ in range(10):
                events += source.read(0.5)
                if len(events) >= 200:
                    break
        finally:
            source.close()
    assert [e.x for e in events] == [100 + k for k in range(200)]
