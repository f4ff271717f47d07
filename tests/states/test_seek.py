"""``replay FILE --seek T`` on every shipped recording: what it shows from T is exactly what the
full replay shows from T, without running the ticks before T again, and ``--check`` still
passes. T is 40 % of each recording's length (inside a CA menu dialogue for fig-7.1)."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.protocols.session import read
from tests.states.support import RECORDINGS, frame_logs


def _seek_time(rec: Path) -> Fraction:
    end = read(rec).end
    assert end is not None
    return end.time * Fraction(2, 5)


@pytest.mark.parametrize("rec", RECORDINGS, ids=lambda p: p.name)
def test_seeking_shows_what_the_full_replay_shows_from_there(monkeypatch, capsys,
                                                             rec: Path) -> None:
    t = _seek_time(rec)
    with frame_logs(monkeypatch) as runs:
        assert main(["replay", str(rec), "--headless"]) == 0
        assert main(["replay", str(rec), "--headless", "--check", "--seek", str(t)]) == 0
    full, ahead, shown = runs
    assert "screen hashes agree" in capsys.readouterr().out
    assert shown, "nothing shown after the seek"
    first = min(k for k in shown if k != "ticks")
    assert first == max(k for k in ahead if k != "ticks") + 1  # from where the seek stopped
    assert shown["ticks"] + ahead["ticks"] == full["ticks"]  # no tick made twice
    assert {k: v for k, v in shown.items() if k != "ticks"} == \
        {k: v for k, v in full.items() if k != "ticks" and k >= first}


def test_a_seek_past_the_end_is_refused_naming_the_end(capsys) -> None:
    rec = RECORDINGS[0]
    assert main(["replay", str(rec), "--headless", "--seek", "100000"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "the recording ends at" in err[0] and str(rec) in err[0]


def test_a_replay_saves_a_state_that_a_replay_loads(tmp_path: Path, monkeypatch) -> None:
    rec = next(r for r in RECORDINGS if r.name == "sigma_run.session")
    state = tmp_path / "r.c88state"
    with frame_logs(monkeypatch) as runs:
        assert main(["replay", str(rec), "--headless", "--save-state", str(state),
                     "--at", "1"]) == 0
        assert main(["replay", str(rec), "--headless", "--check", "--load-state",
                     str(state)]) == 0
    full, rest = runs
    first = min(k for k in rest if k != "ticks")
    assert {k: v for k, v in rest.items() if k != "ticks"} == \
        {k: v for k, v in full.items() if k != "ticks" and k >= first}
    assert rest["ticks"] < full["ticks"]
