"""A replay holds a window of its recording, not all of it: the events, outside input and
screen hashes are read again from the file as the run reaches their ticks and dropped once
fed or compared (emulator/harness/replay_window.py), so a replay's memory does not grow
with the recording's length (docs/reliability.md, "Budget"; docs/performance.md)."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest

from camlab88.emulator.harness.replay_window import RecordWindow
from camlab88.protocols.session import ScreenHash, SessionFileError, SessionRecording, read
from tests.budget import bombs
from tests.budget.measure import camlab88

ROOT = Path(__file__).resolve().parents[2]
STREAM = str(ROOT / "examples" / "sigma" / "pgplot_goc.sig")
KEY_UP = {"kind": "KeyUp", "key": "f15"}


def _long(ticks: int, per_tick: int) -> SessionRecording:
    rec = SessionRecording(["sigma", "run"], 10)
    rec.events = [(t, Fraction(t, 100), KEY_UP) for t in range(ticks) for _ in range(per_tick)]
    rec.wire = [(t, "+", b"x") for t in range(1, ticks)]
    rec.hashes = [ScreenHash(f, f * 4, Fraction(f * 4, 100), "0" * 64)
                  for f in range(10, ticks // 4, 10)]
    rec.end, rec.ticks = ScreenHash(ticks // 4, ticks, Fraction(ticks, 100), "0" * 64), ticks
    return rec


def test_the_window_holds_a_tick_or_two_whatever_the_length() -> None:
    window = RecordWindow(_long(5000, 3))
    most = 0
    for tick in range(5000):
        assert window.wire_at(tick) == ([("+", b"x")] if tick < 4999 else [])
        assert len(window.events_at(tick)) == 3
        if tick % 40 == 0 and tick:
            assert window.hash_at(tick // 4) is not None
        most = max(most, len(window.events) + len(window.wire) + len(window.hashes))
    assert most <= 3 + 1 + 3 + 2, most  # the next tick's records, read ahead to see its end


def test_without_check_no_hash_is_held() -> None:
    window = RecordWindow(_long(2000, 1), hashes=False)
    for tick in range(2000):
        window.events_at(tick)
    assert not window.hashes


def test_a_window_started_late_drops_what_it_passes() -> None:
    """A run from a loaded state (``--seek``) starts at a later tick: the records before
    it are read and dropped, not held."""
    window = RecordWindow(_long(3000, 2))
    assert len(window.events_at(2500)) == 2
    assert len(window.events) <= 2 + 1  # the next tick's, and the one that ended it


def test_a_recording_changed_under_the_replay_is_named(tmp_path: Path) -> None:
    path = tmp_path / "s.session"
    bombs.many_record_session(path, 100, "+")
    rec = read(path, traffic=False)
    with open(path, "a") as fh:
        fh.write("\n")
    with pytest.raises(SessionFileError, match="s.session: changed while it was replayed"):
        list(rec.timeline())
    window = RecordWindow(rec)
    assert window.events_at(0) == [] and window.fault is not None


RATIO = 1.15  # peak RSS of the 10x longer replay over the short one's (measured: 1.00)


@pytest.mark.slow
def test_replay_memory_does_not_grow_with_the_recording_s_length(tmp_path: Path) -> None:
    """A sigma run recorded for 20 s and for 200 s of line time, each given ten events a
    tick (20,000 and 200,000: hours of typing), replayed with --check in a measured child:
    every hash agrees and the longer one's peak RSS is within RATIO of the shorter's
    (before the window: 162 -> 292 MB)."""
    peaks = []
    for seconds in (20, 200):
        plain, padded = f"r{seconds}.session", f"p{seconds}.session"
        made = camlab88(tmp_path, "sigma", "run", "--headless", "--speed", "1000", "--seconds",
                        str(seconds), "--in", STREAM, "--record", plain)
        assert made.status == 0, made.stderr
        bombs.with_idle_events(tmp_path / plain, tmp_path / padded, 10)
        run = camlab88(tmp_path, "replay", padded, "--check", "--headless", timeout=600)
        assert run.status == 0 and "screen hashes agree" in run.stdout, run.stderr
        peaks.append(run.peak_mb)
    assert peaks[1] <= peaks[0] * RATIO, peaks


def test_one_tick_holding_more_than_the_budget_is_one_line(tmp_path: Path) -> None:
    """The window is bounded by the budget too: 100,000 events on one tick (30 MB held)
    against an 8 MB budget end the replay in one line, status 2, before they are fed."""
    bombs.one_tick_of_events(tmp_path / "tick.session", 100000)
    run = camlab88(tmp_path, "replay", "tick.session", "--headless", budget="8M", timeout=120)
    lines = [ln for ln in run.stderr.splitlines() if ln.strip()]
    assert run.status == 2 and len(lines) == 1 and "Traceback" not in run.stderr, run.stderr
    assert lines[0].startswith("camlab88 replay: tick.session: tick 0: its "), lines
    assert "records and more, held for one tick, would need more than the memory budget of 8 MB" \
        in lines[0], lines
    assert "--budget SIZE" in lines[0] and run.peak_mb <= 400, (lines, run.peak_mb)
