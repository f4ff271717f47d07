"""``sigma run --record-line`` stopped by SIGTERM (kill, a service manager) still writes its
recording, as Ctrl-C does (docs/newcomer_trial.md)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path


def test_sigma_run_headless_writes_the_line_recording_on_sigterm(tmp_path: Path) -> None:
    rec = tmp_path / "s.rec"
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER")}
    proc = subprocess.Popen(
        [sys.executable, "-m", "camlab88", "sigma", "run", "--record-line", str(rec)],
        cwd=tmp_path, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        first = proc.stdout.readline()  # the pty is open: the run loop is about to start
        assert "on pty" in first, first
        proc.send_signal(signal.SIGTERM)
        out, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert "until Ctrl-C" in err  # the headless run says how it ends
    assert f"recorded the line to {rec}" in out, (out, err)
    assert rec.read_text(encoding="utf-8").startswith("camlab88-link-recording 1\n")
    assert "Traceback" not in err
