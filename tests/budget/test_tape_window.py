"""A replay holds a window of its tablet tape, not all of it: the tape's ``T`` records are
read again from the file as the replay's polls reach them and dropped once passed
(protocols/tablets/tape.py ``Tape``), so a replay's memory does not grow with the tape's
length (docs/reliability.md, "Budget"; docs/performance.md, "Replay memory")."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from camlab88.protocols.session import read
from camlab88.protocols.tablets.tape import Tape
from tests.budget import bombs
from tests.budget.measure import camlab88

SCRIPT = ("0.2 move 0 0\n0.4 down 0 0\n0.6 down 1 1\n0.8 down 2 1\n1.0 up 2 1\n"
          "1.5 key f2\n20 wait\n")
RATIO = 1.15  # peak RSS of the replay of the 10x longer tape over the short one's


def _records(polls: int, per_poll: int) -> list[bytes]:
    """A tape of ``polls`` records (one a poll) of ``per_poll`` empty reads each."""
    return [json.dumps([[p, "raw", ""]] * per_poll).encode() for p in range(polls)]


def test_the_tape_holds_a_poll_or_two_whatever_its_length() -> None:
    chunks = _records(3000, 4)
    read_so_far = []

    def records():
        for data in chunks:
            read_so_far.append(data)
            yield data

    tape = Tape(records=records)
    most = 0
    for poll in range(3000):
        tape.poll = poll
        assert tape.here() == [("raw", "")] * 4
        assert len(read_so_far) <= poll + 2  # read as the polls reach it, not ahead
        most = max(most, sum(len(v) for v in tape.by_poll.values()))
    assert most <= 4 + 4, most  # this poll's, and the next one's (read to see its end)


def test_a_loaded_state_s_tape_reads_on_from_where_it_was_saved() -> None:
    """``--seek``/``--load-state``: a fresh tape given a saved one's counters (its reading
    is not saved) reads the entries after them, not the tape again from the start."""
    chunks = [json.dumps([[p, "idle", p % 3]]).encode() for p in range(100)]
    saved = Tape(records=lambda: iter(chunks))
    saved.poll = 40
    saved.here()
    fresh = Tape(records=lambda: iter(chunks))
    fresh.here()  # a fresh graph reads its first poll before the state is loaded
    fresh.__dict__.update({k: v for k, v in vars(saved).items()
                           if k not in Tape._state_exclude})
    for poll in range(40, 100):
        fresh.poll = poll
        assert fresh.here() == [("idle", poll % 3)]


def test_a_poll_holding_more_than_the_budget_is_a_fault(monkeypatch) -> None:
    monkeypatch.setenv("CAMLAB88_BUDGET", "1M")
    faults: list[str] = []
    tape = Tape(records=lambda: iter(_records(1, 100000)), on_fault=faults.append)
    tape.here()
    assert len(faults) == 1 and "poll 0: its " in faults[0], faults
    assert "held at once, would need more than the memory budget of 1 MB" in faults[0]


def test_the_first_pass_keeps_none_of_the_tape(tmp_path: Path, monkeypatch) -> None:
    path = _recorded(tmp_path, monkeypatch, "2.5 wait\n")
    rec = read(path, traffic=False)
    assert not rec.wire  # the replay's reading: no T record held
    assert sum(1 for _ in rec.tape_records()) == sum(
        1 for w in read(path).wire if w[1] == "T") > 10


def _recorded(tmp_path: Path, monkeypatch, end: str = "20 wait\n") -> Path:
    monkeypatch.setenv("CAMLAB88_CONFIG_DIR", str(tmp_path / "config"))
    (tmp_path / "s.txt").write_text(SCRIPT.replace("20 wait\n", end))
    made = camlab88(tmp_path, "kas", "edit", "k.kas", "--tablet", "emulated:summa-mm",
                    "--headless", "--speed", "1000", "--script", "s.txt", "--record",
                    "base.session")
    assert made.status == 0, made.stderr
    return tmp_path / "base.session"


@pytest.mark.slow
def test_replay_memory_does_not_grow_with_the_tape_s_length(tmp_path: Path,
                                                            monkeypatch) -> None:
    """A kas edit session with an emulated streaming tablet (20 s, 2,000 polls), its tape
    padded with 20 and with 200 empty reads a poll (40,000 and 400,000 entries), replayed
    with --check in a measured child: every hash agrees and the longer one's peak RSS is
    within RATIO of the shorter's (with the whole tape held: 164 -> 257 MB)."""
    base = _recorded(tmp_path, monkeypatch)
    peaks = []
    for per_poll in (20, 200):
        padded = bombs.with_empty_reads(base, tmp_path / f"p{per_poll}.session", per_poll)
        run = camlab88(tmp_path, "replay", padded.name, "--check", "--headless", timeout=600)
        assert run.status == 0 and "screen hashes agree" in run.stdout, run.stderr
        peaks.append(run.peak_mb)
    assert peaks[1] <= peaks[0] * RATIO, peaks


def test_one_poll_holding_more_than_the_budget_ends_the_replay_in_one_line(
        tmp_path: Path, monkeypatch) -> None:
    """100,000 entries on one poll (20 MB held) against an 8 MB budget: one line, status 2."""
    import base64
    import zlib

    path = _recorded(tmp_path, monkeypatch, "2.5 wait\n")
    lines = path.read_text().splitlines()
    at = next(n for n, ln in enumerate(lines) if '"dir":"T"' in ln)
    obj = json.loads(lines[at])
    entries = json.loads(zlib.decompress(base64.b64decode(obj["data"])))
    entries += [[entries[-1][0], "raw", ""]] * 100000
    obj["data"] = base64.b64encode(zlib.compress(json.dumps(entries).encode(), 9)).decode()
    lines[at] = json.dumps(obj, separators=(",", ":"))
    (tmp_path / "poll.session").write_text("\n".join(lines) + "\n")
    run = camlab88(tmp_path, "replay", "poll.session", "--check", "--headless", budget="8M")
    said = [ln for ln in run.stderr.splitlines() if ln.strip()]
    assert run.status == 2 and len(said) == 1 and "Traceback" not in run.stderr, run.stderr
    assert said[0].startswith("camlab88 replay: poll.session: the recording's tablet tape: "
                              "poll 0: its "), said
    assert "held at once, would need more than the memory budget of 8 MB" in said[0], said
