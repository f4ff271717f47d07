"""``sigma run --serial`` on a port that goes away and comes back: the failure is reported
once (not at every retry) and the port's return is reported.  The port is one end of a socat
null modem; socat is stopped (the pty vanishes) and started again on the same path."""

from __future__ import annotations

import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

GUARD = 20.0  # wall seconds any wait here may take (a guard against hangs)


def _socat(a: Path, b: Path) -> subprocess.Popen:
    proc = subprocess.Popen(["socat", f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + GUARD
    while not (a.exists() and b.exists()) and time.monotonic() < deadline:
        time.sleep(0.02)
    assert a.exists() and b.exists(), "socat made no ptys"
    return proc


def _stop(proc: subprocess.Popen) -> None:
    if proc.poll() is None:
        proc.terminate()
        proc.wait(GUARD)


def _wait_for(stream_lines: list[str], text: str, proc: subprocess.Popen) -> None:
    deadline = time.monotonic() + GUARD
    while not any(text in s for s in stream_lines) and time.monotonic() < deadline:
        if proc.poll() is not None:
            break
        time.sleep(0.05)


def test_a_port_that_goes_and_comes_back_is_reported_once_each_way(tmp_path: Path) -> None:
    if shutil.which("socat") is None:
        pytest.skip("socat is not installed (apt-get install socat)")
    import threading

    a, b = tmp_path / "end_a", tmp_path / "end_b"
    modem = _socat(a, b)
    run = subprocess.Popen(
        [sys.executable, "-m", "camlab88", "sigma", "run", "--headless", "--serial", str(a),
         "--seconds", "8"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    err: list[str] = []
    reader = threading.Thread(target=lambda: err.extend(run.stderr), daemon=True)
    try:
        first = run.stdout.readline()
        assert "on serial port" in first, first
        reader.start()
        _stop(modem)  # the cable is pulled: the port fails, and reopening it fails
        _wait_for(err, "disconnected", run)
        time.sleep(1.5)  # about six retries, all failing the same way
        modem = _socat(a, b)
        _wait_for(err, "is back", run)
        out, _ = run.communicate(timeout=GUARD)
        reader.join(GUARD)
    finally:
        _stop(modem)
        if run.poll() is None:
            run.kill()
            run.wait()
    text = "".join(err)
    assert run.returncode == 0, text
    assert text.count("camlab88 sigma: disconnected: ") == 1, text
    assert text.count("cannot open") <= 1, text  # a retry failing again is not news
    assert text.count(f"{a} is back") == 1, text
