"""SIGTERM (kill, a service manager, a CI timeout) ends any command the way Ctrl-C does:
a headless run's ``--record`` file is finished and written, and the exit status is 143
(a headless ``rainbow run --record`` killed by SIGTERM once wrote nothing)."""

from __future__ import annotations

import os
import signal
from pathlib import Path

import pytest

from camlab88 import cli
from camlab88.emulator.harness.loop import Harness
from camlab88.protocols.session import format as session_format


def test_sigterm_mid_run_writes_the_recording_and_exits_143(tmp_path: Path,
                                                            monkeypatch: pytest.MonkeyPatch
                                                            ) -> None:
    show = Harness._show

    def show_then_terminate(self: Harness) -> None:
        show(self)
        if self.frames_shown == 25:  # past two of the every-10-frames hashes
            os.kill(os.getpid(), signal.SIGTERM)  # delivered to this, the main, thread

    monkeypatch.setattr(Harness, "_show", show_then_terminate)
    before = signal.getsignal(signal.SIGTERM)
    rec = tmp_path / "r.session"
    status = cli.main(["rainbow", "run", "--headless", "--stop-after", "100000",
                       "--record", str(rec)])
    assert status == 143
    assert signal.getsignal(signal.SIGTERM) == before  # the handler is put back
    session = session_format.read(str(rec))  # whole: it has its end record
    assert session.hashes and session.end is not None

