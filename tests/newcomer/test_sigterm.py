"""``sigma run --record-line`` stopped by SIGTERM (kill, a service manager) still writes its
recording, as Ctrl-C does (docs/newcomer_trial.md)."""

from __future__ import annotations

import os
import signal
import sys
import time
from pathlib import Path

import pytest

from tests.support.processes import child


def test_sigma_run_headless_writes_the_line_recording_on_sigterm(tmp_path: Path) -> None:
    rec = tmp_path / "s.rec"
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER")}
    with child([sys.executable, "-m", "camlab88", "sigma", "run", "--record-line", str(rec)],
               cwd=tmp_path, env=env) as proc:
        first = proc.stdout.readline()  # the pty is open: the run loop is about to start
        assert "on pty" in first, first
        proc.send_signal(signal.SIGTERM)
        out, err = proc.communicate(timeout=60)
    assert "until Ctrl-C" in err  # the headless run says how it ends
    assert f"recorded the line to {rec}" in out, (out, err)
    assert rec.read_text(encoding="utf-8").startswith("camlab88-link-recording 1\n")
    assert "Traceback" not in err


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGHUP], ids=["SIGTERM", "SIGHUP"])
def test_sigma_run_writes_trace_recording_and_screenshot_on_sigterm_and_sighup(
        tmp_path: Path, sig: int) -> None:
    """SIGHUP (the terminal closed) writes what SIGTERM writes; 129 and 143 as the shell says."""
    rec, trace, shot = tmp_path / "s.rec", tmp_path / "s.jsonl", tmp_path / "s.png"
    with child([sys.executable, "-m", "camlab88", "sigma", "run", "--headless", "--seconds",
                "600", "--record-line", str(rec), "--trace", str(trace), "--screenshot",
                str(shot)], cwd=tmp_path) as proc:
        first = proc.stdout.readline()
        assert "on pty" in first, first
        with open(first.split()[-1], "wb", buffering=0) as host:
            host.write(b"\r\n+-*/")  # something for the trace to hold
            time.sleep(1.0)  # wall time for the run loop to start and take the bytes
        proc.send_signal(sig)
        out, err = proc.communicate(timeout=60)
    assert proc.returncode == (129 if sig == signal.SIGHUP else 143), err
    assert rec.read_text(encoding="utf-8").startswith("camlab88-link-recording 1\n")
    assert shot.exists() and f"screenshot {shot}" in err, (out, err)
    assert "traced 2 orders" in err, err  # CR LF as alpha text, then the graphics flag
    assert "Traceback" not in err
