"""``--record`` writes the session as it runs (protocols/session/writer.py): to a temporary
file beside the target, renamed into place at the end, so the recorder's memory does not grow
with the session's length and an interrupted run leaves no half file under the target's name
(docs/reliability.md, "Budget"; docs/performance.md, "Replay memory")."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from fractions import Fraction
from pathlib import Path

from camlab88.protocols.session import ScreenHash, SessionRecording, read
from camlab88.protocols.session.format import dumps
from camlab88.protocols.session.writer import SessionWriter
from tests.budget.measure import ROOT, camlab88

SCRIPT = ("0.2 move 0 0\n0.4 down 0 0\n0.6 down 1 1\n0.8 down 2 1\n1.0 up 2 1\n"
          "1.5 key f2\n{end} wait\n")
KEY = {"kind": "KeyUp", "key": "f15"}


def _session(ticks: int) -> SessionRecording:
    """A session as a recorder meets it, in the order it meets it within a tick."""
    rec = SessionRecording(["sigma", "run"], 10, True, {"x.sig": b"\x1b"})
    for t in range(ticks):
        rec.events += [(t, Fraction(t, 100), KEY)] * 2
        rec.wire += [(t, "T", b"[]"), (t, ">", bytes([t % 256]) * 3)]
        if t % 40 == 39:
            rec.hashes.append(ScreenHash(len(rec.hashes) * 10 + 10, t, Fraction(t, 100),
                                         "0" * 64))
    rec.end, rec.ticks = ScreenHash(ticks // 4, ticks, Fraction(ticks, 100), "1" * 64), ticks
    return rec


def test_the_writer_holds_one_tick_and_writes_the_bytes_dumps_writes(tmp_path: Path) -> None:
    rec = _session(4000)
    out = SessionWriter(tmp_path / "s.session", rec.argv, 10, True, rec.files)
    most = 0
    hashes = iter(rec.hashes)
    h = next(hashes)
    for t in range(rec.ticks):  # each tick's wire before its events: the writer sorts
        for w in rec.wire[2 * t:2 * t + 2]:
            out.wire(*w)
        for e in rec.events[2 * t:2 * t + 2]:
            out.event(*e)
        if h is not None and h.tick == t:
            out.hash(h)
            h = next(hashes, None)
        most = max(most, len(out._held))
        assert not (tmp_path / "s.session").exists()  # only at the end, whole
    out.finish(rec.end, rec.ticks)
    assert most <= 5, most
    assert (tmp_path / "s.session").read_text() == dumps(rec)
    assert [p.name for p in tmp_path.iterdir()] == ["s.session"]


def test_an_abandoned_recording_leaves_the_older_file(tmp_path: Path) -> None:
    target = tmp_path / "s.session"
    target.write_text("older\n")
    out = SessionWriter(target, ["sigma", "run"], 10, True, {})
    out.event(0, Fraction(0), KEY)
    out.abandon()
    assert [p.name for p in tmp_path.iterdir()] == ["s.session"]
    assert target.read_text() == "older\n"


def test_a_killed_record_run_leaves_no_half_file(tmp_path: Path) -> None:
    """A ``--record`` run killed (SIGKILL: no chance to clean up) half way: the older
    recording under the target's name is untouched; the temporary file it leaves (named
    with its pid) is swept by the next writer to that name, whose recording replays."""
    target = tmp_path / "r.session"
    target.write_text("older\n")
    env = {**os.environ, "PYTHONPATH": str(ROOT), "SDL_VIDEODRIVER": "dummy"}
    child = subprocess.Popen([sys.executable, "-m", "camlab88", "sigma", "run", "--headless",
                              "--speed", "1", "--seconds", "600", "--record", target.name],
                             cwd=tmp_path, env=env, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 120
        while not any(p.name.startswith(".r.session.") for p in tmp_path.iterdir()):
            assert time.monotonic() < deadline and child.poll() is None, "no temporary file"
            time.sleep(0.1)
        time.sleep(1.0)  # some ticks written
    finally:
        child.send_signal(signal.SIGKILL)
        child.wait()
    assert target.read_text() == "older\n"
    left = [p for p in tmp_path.iterdir() if p != target]
    assert len(left) == 1 and left[0].name.startswith(f".r.session.{child.pid}."), left
    made = camlab88(tmp_path, "sigma", "run", "--headless", "--seconds", "0.2", "--record",
                    target.name)
    assert made.status == 0, made.stderr
    assert [p.name for p in tmp_path.iterdir() if not p.name.startswith("_")] == [target.name]
    assert read(target).end is not None
