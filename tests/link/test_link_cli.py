from __future__ import annotations

import argparse
import io
import socket
import threading
from pathlib import Path

import pytest

from camlab88.protocols.link import LineSettings, Recorder, SerialLine
from camlab88.protocols.link.cli import dump, main, printable, run_echo, write_stream
from camlab88.protocols.link.transports import TcpBridge


def make_recording(path: Path) -> None:
    line = SerialLine(recorder=Recorder(path, LineSettings()))
    line.host.write(b"\r+-*/\x00\x13")
    line.device.write(b"ok\\")
    line.close()


def test_dump_is_readable(tmp_path: Path) -> None:
    rec = tmp_path / "a.rec"
    make_recording(rec)
    out = io.StringIO()
    assert dump(str(rec), out) == 0
    text = out.getvalue()
    assert "\\r+-*/\\x00\\x13" in text and "ok\\x5c" in text
    assert "host to device: 7 bytes" in text
    assert printable(b"\n\x7f") == "\\n\\x7f"


def test_bad_recording_is_an_error_not_a_traceback(tmp_path: Path, capsys) -> None:
    bad = tmp_path / "bad.rec"
    bad.write_text("hello\n")
    assert main(["dump", str(bad)]) == 2
    assert f"{bad}:1: not a camlab88 link recording" in capsys.readouterr().err


def test_stream_writes_what_the_device_received(tmp_path: Path) -> None:
    rec = tmp_path / "a.rec"
    make_recording(rec)
    out = tmp_path / "s.bin"
    assert write_stream(str(rec), str(out), ">") == 0
    assert out.read_bytes() == b"\r+-*/\x00"  # the DC3 was flow control, not data


def test_echo_device_over_tcp() -> None:
    line = SerialLine()
    stop = threading.Event()
    with TcpBridge(0, endpoint=line.host) as bridge:
        result: list[int] = []
        worker = threading.Thread(
            target=lambda: result.append(run_echo(bridge, line, seconds=20, stop=stop))
        )
        worker.start()
        try:
            client = socket.create_connection(("127.0.0.1", bridge.port), timeout=10)
            client.sendall(b"ping")
            got = b""
            while len(got) < 4:
                more = client.recv(4)
                assert more
                got += more
            assert got == b"ping"
            client.close()
        finally:
            stop.set()
            worker.join(timeout=10)
    assert result == [4]


def test_link_dump_of_a_session_recording_says_which_flag_makes_which(tmp_path: Path,
                                                                      capsys) -> None:
    from camlab88.cli import main as camlab88_main

    session = Path(__file__).parents[1] / "data" / "sessions" / "sigma_run.session"
    assert camlab88_main(["link", "dump", str(session)]) == 2
    err = capsys.readouterr().err
    assert "is a session recording, not a link recording" in err
    assert "--record-line FILE` writes the link recording" in err
    rec = tmp_path / "a.rec"
    make_recording(rec)  # a real link recording still dumps through the command
    assert camlab88_main(["link", "dump", str(rec)]) == 0


def _tool_options(parser: argparse.ArgumentParser, *path: str) -> list[tuple]:
    for name in path:
        sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
        parser = sub.choices[name]
    return [(tuple(a.option_strings), a.dest, a.default, a.help) for a in parser._actions]


@pytest.mark.parametrize("tool", ["echo", "stream"])
def test_camlab88_link_and_python_m_protocols_link_share_one_parser(tool: str) -> None:
    from camlab88.cli import build_parser
    from camlab88.protocols.link.cli import add_tools

    standalone = argparse.ArgumentParser()
    add_tools(standalone)
    assert _tool_options(build_parser(), "link", tool) == _tool_options(standalone, tool)
