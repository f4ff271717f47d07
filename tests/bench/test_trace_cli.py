"""--trace and --strict on the commands that decode a device protocol, and link dump
--decode: a stream with one bad order gives a trace line, and with --strict exit 1 naming
its offset, time, the bytes before it and what was expected."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from PIL import Image

from camlab88.cli import main

BAD = b"\r+-*/HI2GI200200GJ600200QQ600400BH"  # QQ at byte 24


def _lines(path: Path) -> list[dict]:
    return [json.loads(line) for line in path.read_text().splitlines()]


def test_render_trace_names_every_order_and_the_bad_one(tmp_path):
    src, trace = tmp_path / "bad.sig", tmp_path / "t.jsonl"
    src.write_bytes(BAD)
    assert main(["sigma", "render", "--in", str(src), "--out", str(tmp_path / "a.png"),
                 "--trace", str(trace)]) == 0
    got = _lines(trace)
    assert [e["order"] for e in got][:7] == ["alpha", "+-*/", "HI", "GI", "pair", "GJ", "pair"]
    bad = [e for e in got if "warning" in e]
    assert [(e["offset"], e["kind"]) for e in bad] == [(24, "unknown"), (25, "unknown")]
    assert bad[0]["time"] == round(25 / 960, 9)  # byte 24 is the 25th to arrive
    assert got[4]["args"] == {"x": 100, "y": 100, "pen": "move"}


def test_render_strict_exits_1_naming_offset_time_bytes_and_expectation(tmp_path, capsys):
    src = tmp_path / "bad.sig"
    src.write_bytes(BAD)
    out = tmp_path / "a.png"
    assert main(["sigma", "render", "--in", str(src), "--out", str(out), "--strict"]) == 1
    err = capsys.readouterr().err
    assert f"{src}: byte 24 (t=0.026042 s): unknown byte 0x51" in err
    assert "b'200GJ600200Q'" in err and "expected an order letter" in err
    assert "bytes from it on: b'QQ600400BH'" in err
    assert not out.exists()  # nothing is written from a stream strict mode refused


def test_render_strict_passes_a_clean_stream_and_the_picture_is_unchanged(tmp_path):
    src = tmp_path / "good.sig"
    src.write_bytes(BAD.replace(b"QQ", b""))
    plain, strict = tmp_path / "plain.png", tmp_path / "strict.png"
    assert main(["sigma", "render", "--in", str(src), "--out", str(plain)]) == 0
    assert main(["sigma", "render", "--in", str(src), "--out", str(strict), "--strict",
                 "--trace", str(tmp_path / "t.jsonl")]) == 0
    a, b = (np.asarray(Image.open(p).convert("RGB")) for p in (plain, strict))
    assert np.array_equal(a, b) and a.any()


def test_sigma_run_traces_the_line_and_strict_stops_it(tmp_path, capsys):
    src, trace = tmp_path / "bad.sig", tmp_path / "run.jsonl"
    src.write_bytes(BAD)
    args = ["sigma", "run", "--headless", "--in", str(src), "--seconds", "0.2"]
    assert main([*args, "--trace", str(trace)]) == 0
    assert [e["offset"] for e in _lines(trace) if "warning" in e] == [24, 25]
    assert main([*args, "--strict"]) == 1
    assert "camlab88 sigma run: the line: byte 24 (t=0.026042 s)" in capsys.readouterr().err


def test_rainbow_run_traces_the_command_stream(tmp_path):
    trace = tmp_path / "rb.jsonl"
    assert main(["rainbow", "run", "--headless", "--stop-after", "2", "--trace",
                 str(trace)]) == 0
    got = _lines(trace)
    assert got[0]["order"] == "hello" and got[0]["offset"] == 0
    assert any(e["order"] == "create_pad" for e in got)
    assert sum(e["order"] == "wait_frame" for e in got) == 2
    assert not any("warning" in e for e in got)


def test_link_dump_decode_shows_orders_and_replies(tmp_path, capsys):
    from fractions import Fraction

    from camlab88.protocols.link import LineSettings
    from camlab88.protocols.link.recording import Recorder

    rec = tmp_path / "s.rec"
    with Recorder(rec, LineSettings()) as r:
        r.record(Fraction(len(BAD), 960), ">", BAD)
        r.record(Fraction(1), "<", b"A468,356\r")
    assert main(["link", "dump", "--decode", str(rec)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert any("      24 0x51" in line and "!! unknown" in line for line in out)
    assert out[-2].endswith("< b'A468,356\\r'") and out[-1] == "# 2 protocol warnings"


def _serve(tmp_path, *extra):
    import os
    import subprocess
    import sys

    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[2]))
    proc = subprocess.Popen([sys.executable, "-m", "camlab88", "rainbow", "serve", "--headless",
                             "--port", "0", "--connections", "1", *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    line = proc.stdout.readline()
    assert "listening on 127.0.0.1:" in line, line + proc.stderr.read()
    return proc, int(line.rsplit(":", 1)[1])


def test_rainbow_serve_traces_and_strict_stops_at_the_first_refusal(tmp_path):
    import pytest

    from camlab88.protocols.rainbow import RainbowClient, RainbowRefused, SocketTransport
    from camlab88.protocols.rainbow.stream import StreamError

    trace = tmp_path / "serve.jsonl"
    proc, port = _serve(tmp_path, "--trace", str(trace), "--strict-protocol")
    try:
        client = RainbowClient(SocketTransport(port, timeout=10))
        assert client.hello()["screen_w"] == 768
        with pytest.raises((StreamError, RainbowRefused, OSError)):
            client.destroy(99)  # refused: strict mode ends the server
        client.close()
        _out, err = proc.communicate(timeout=20)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 1
    assert "camlab88 rainbow serve: the command stream: byte 5 (t=0.000000 s): destroy" in err
    got = _lines(trace)
    assert [e["order"] for e in got] == ["hello", "destroy"]
    assert got[1]["kind"] == "refused" and "no node 99" in got[1]["warning"]
