"""Ctrl-C on ``snooker film --dask local``: the terminal sends SIGINT to the whole process
group (the command and its worker processes); the command answers in one line, exit 130,
and no worker prints a traceback or its cancelled frames."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

from tests.snooker_film.helpers import BREAK, SCRIPT

ROOT = Path(__file__).resolve().parents[2]


def _default_sigint() -> None:  # a shell's background job starts with SIGINT ignored
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def test_ctrl_c_on_a_local_dask_film_is_one_line(tmp_path: Path) -> None:
    frames = tmp_path / "f_frames"
    proc = subprocess.Popen(
        [sys.executable, "-m", "camlab88", "snooker", "film", str(BREAK), str(SCRIPT), "--out",
         str(tmp_path / "f.mp4"), "--size", "96x64", "--dask", "local", "--workers", "2",
         "--motion-blur", "--blur-samples", "16"],
        start_new_session=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        env={**os.environ, "PYTHONPATH": str(ROOT)}, preexec_fn=_default_sigint)
    try:
        deadline = time.monotonic() + 240
        while len(list(frames.glob("frame_*.png"))) < 2 and proc.poll() is None:
            assert time.monotonic() < deadline, "no frame rendered in 240 s"
            time.sleep(0.2)
        assert proc.poll() is None, "the film ended before the test could interrupt it"
        os.killpg(proc.pid, signal.SIGINT)  # what Ctrl-C in the terminal does
        _out, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
    assert proc.returncode == 130
    # the command's one line, last; nothing from the workers' interrupted frames (on a
    # loaded machine Dask may still log that its event loop was slow: that is not Ctrl-C's)
    lines = err.strip().splitlines()
    assert lines[-1] == ("camlab88 snooker film: interrupted; the frames written so far "
                         "stay, and the same command resumes from them"), err
    for noise in ("Traceback", "KeyboardInterrupt", "CancelledError", "interrupted;"):
        assert sum(noise in line for line in lines) == (noise == "interrupted;"), err


def test_a_workers_heartbeat_that_finds_the_scheduler_gone_prints_nothing() -> None:
    """A worker's heartbeat that races the command's stop (the scheduler is in the command's
    process, so it is gone only then) logs a traceback at ERROR through distributed's
    ``logger.exception``: after the preload it prints nothing, and a worker's other errors
    still print. Run in a child: the preload changes the process's logging."""
    code = (
        "import logging, sys\n"
        "logging.basicConfig(stream=sys.stderr, format='%(name)s %(message)s')\n"
        "from camlab88.apps.snooker.film.quiet_worker import dask_setup\n"
        "dask_setup(None)\n"
        "log = logging.getLogger('distributed.worker')\n"
        "try:\n"
        "    raise OSError('connection refused')\n"
        "except OSError:\n"
        "    log.exception('Failed to communicate with scheduler during heartbeat.')\n"
        "    log.exception('Unexpected exception during heartbeat. Closing worker.')\n"
        "log.warning('a cancelled frame')\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={**os.environ, "PYTHONPATH": str(ROOT)}, timeout=60)
    assert done.returncode == 0, done.stderr
    assert "Failed to communicate" not in done.stderr
    assert "distributed.worker Unexpected exception during heartbeat" in done.stderr
    assert "cancelled frame" not in done.stderr
