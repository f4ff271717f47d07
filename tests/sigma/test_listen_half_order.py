"""A ``--listen`` client that leaves half an order and goes: the order is counted malformed
and ``--strict`` exits 1 naming it, as the same bytes cut short over ``--pty`` are."""

from __future__ import annotations

import socket
import subprocess
import sys

import pytest

from tests.support.processes import child

HALF = b"\r\n+-*/DD000CBGAAAHE999C"  # PGPLOT's start, cut after an order's first letter


def _run(strict: bool) -> subprocess.CompletedProcess:
    argv = [sys.executable, "-m", "camlab88", "sigma", "run", "--headless", "--listen", "0",
            "--seconds", "2", *(["--strict"] if strict else [])]
    with child(argv) as proc:
        first = proc.stdout.readline()
        assert "listening on 127.0.0.1:" in first, first + proc.stderr.read()
        with socket.create_connection(("127.0.0.1", int(first.rsplit(":", 1)[1])), 10) as s:
            s.sendall(HALF)
        out, err = proc.communicate(timeout=60)
    return subprocess.CompletedProcess(argv, proc.returncode, first + out, err)


@pytest.mark.parametrize("strict", [False, True])
def test_half_order_at_disconnect_is_reported(strict: bool) -> None:
    got = _run(strict)
    if strict:
        assert got.returncode == 1, got.stdout + got.stderr
        assert "the client hanging up cuts an order short" in got.stderr
        assert "expected an order of the table: after 'C'" in got.stderr
    else:
        assert got.returncode == 0, got.stderr
        assert f"{len(HALF)} bytes in, 0 unknown and 1 malformed orders skipped" in got.stdout
