"""A `sigma run` session fed by an outside program replays exactly: what came from outside
is recorded at the tick it entered the line (and the line hanging up between TCP clients at
its tick), a replay feeds it back at the same point of the same tick without opening any pty
or socket, and Ctrl-C ends the recorded run between ticks. Real pty and 127.0.0.1 sockets
the test opens; the writers pause at random (seeded); every wait bounded."""

from __future__ import annotations

import random
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

from camlab88.protocols.session import read
from tests.support.listeners import port_of, start, stop, wait_idle

ORDERS = b"\r+-*/HI2GI200200GJ600200600400200400200200"


@pytest.fixture(scope="module", autouse=True)
def _kernels_compiled(tmp_path_factory: pytest.TempPathFactory) -> None:
    """Draw the orders once first, so the session's first drawing does not stop for the
    kernels' compilation (seconds) while the writer has long finished."""
    where = tmp_path_factory.mktemp("warm")
    (where / "orders.sigma").write_bytes(ORDERS)
    subprocess.run([sys.executable, "-m", "camlab88", "sigma", "render", "--in",
                    str(where / "orders.sigma"), "--out", str(where / "x.png")],
                   capture_output=True, timeout=300, check=True)


def _replay_check(session: Path, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "camlab88", "replay", str(session), "--check",
                           "--headless"], cwd=cwd, capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize("seed", [1, 7])
def test_a_session_fed_through_the_pty_replays_with_check(tmp_path: Path, seed: int) -> None:
    serial = pytest.importorskip("serial")
    session = tmp_path / "s.session"
    proc, first = start(["sigma", "run", "--pty", "--headless", "--record", str(session)],
                        cwd=str(tmp_path))
    rng = random.Random(seed)
    try:
        assert "on pty" in first, first
        port = serial.Serial(first.split()[-1], 9600, timeout=0.1)
        for i in range(0, len(ORDERS), 5):  # in pieces, pausing at random between them
            port.write(ORDERS[i:i + 5])
            port.flush()
            time.sleep(rng.uniform(0.0, 0.25))
        time.sleep(rng.uniform(0.0, 0.4))
        assert wait_idle(proc.pid)  # every byte drawn before the Ctrl-C
        port.close()
    finally:
        out, err = stop(proc)  # Ctrl-C
    assert "recorded the session" in err, err
    rec = read(session)
    assert b"".join(d for _, k, d in rec.wire if k == "+") == ORDERS
    done = _replay_check(session, tmp_path)
    assert done.returncode == 0, done.stderr
    assert "screen hashes agree" in done.stdout
    assert "on pty" not in done.stdout  # the replay opened no pty: the recording fed it


def test_a_listen_session_with_a_client_leaving_replays_with_check(tmp_path: Path) -> None:
    session = tmp_path / "l.session"
    # --speed 1: the line paced even while busy, so A's 2.5 s of bytes are still queued when
    # B comes (unpaced, a busy line runs as fast as A writes and has nothing left to drop)
    proc, first = start(["sigma", "run", "--listen", "0", "--headless", "--speed", "1",
                         "--record", str(session)], cwd=str(tmp_path))
    rng = random.Random(3)
    try:
        port = port_of(first)
        with socket.create_connection(("127.0.0.1", port), timeout=5) as a:
            a.sendall(ORDERS + b"GI" + b"300300" * 400)  # 2.5 s of line time: cut short
            time.sleep(rng.uniform(0.5, 0.9))
        time.sleep(0.1)
        with socket.create_connection(("127.0.0.1", port), timeout=5) as b:
            for piece in (b"\r+-*/HI3GI100100", b"GJ700450", b"700050"):
                b.sendall(piece)
                time.sleep(rng.uniform(0.0, 0.3))
            assert wait_idle(proc.pid)
    finally:
        out, err = stop(proc)
    assert "recorded the session" in err, err
    kinds = [k for _, k, _ in read(session).wire if k in "+-"]
    assert "-" in kinds  # the line hung up when B came, with A's bytes still queued
    done = _replay_check(session, tmp_path)
    assert done.returncode == 0, done.stderr
    assert "listening" not in done.stdout  # the replay opened no socket
