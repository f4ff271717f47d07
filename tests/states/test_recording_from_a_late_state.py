"""A recording of a run begun from ``--load-state`` replays with ``--check`` whenever the state
was saved: its first screen hash is the state's frame (any frame, the recorder's ``start``), the
rest every multiple of ``hash_every`` after it. Before, one saved after frame 10 failed its own
check ("the screen hashes stop at frame 0")."""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

from camlab88.protocols.session.format import read
from fuzz.states import run_cli

LIMIT_S = 60.0
RUN = ["ca", "program", "--headless", "--pattern", "glider", "--events", "e.events"]


@pytest.fixture()
def resumed(tmp_path: Path) -> Iterator[Path]:
    """A CA program recording begun from a state saved at 0.86 s (frame 43: past frame 10
    and no multiple of 10)."""
    old = Path.cwd()
    os.chdir(tmp_path)
    try:
        Path("e.events").write_text("frames 2\nclick middle 400 300\nframes 2\nkey space\n"
                                    "frames 60\n")
        code, err = run_cli([*RUN, "--save-state", "s.c88state", "--at", "0.86"], LIMIT_S)
        assert code == 0, err
        code, err = run_cli([*RUN, "--load-state", "s.c88state", "--record", "r.session"],
                            LIMIT_S)
        assert code == 0, err
        yield tmp_path / "r.session"
    finally:
        os.chdir(old)


def test_it_replays_with_check_its_first_hash_the_state_s_frame(resumed: Path) -> None:
    rec = read(resumed)
    assert rec.hashes[0].frame == 43 and [h.frame for h in rec.hashes[1:]] == [50, 60]
    code, err = run_cli(["replay", str(resumed), "--check"], LIMIT_S)
    assert code == 0, err  # the first hash compared too: the next test changes it


def test_a_changed_first_hash_is_a_mismatch_at_the_state_s_frame(resumed: Path) -> None:
    lines = resumed.read_text().splitlines(keepends=True)
    at = next(i for i, line in enumerate(lines) if '"frame":43' in line)
    lines[at] = re.sub(r'"sha256":"[0-9a-f]{64}"', '"sha256":"' + "0" * 64 + '"', lines[at])
    resumed.write_text("".join(lines))
    code, err = run_cli(["replay", str(resumed), "--check"], LIMIT_S)
    assert code == 1, err
    assert "frame 43" in err, err


def test_only_a_resumed_run_may_hash_a_first_frame_off_the_multiples(resumed: Path) -> None:
    text = resumed.read_text()
    assert ',"--load-state","s.c88state"' in text
    resumed.write_text(text.replace(',"--load-state","s.c88state"', ""))
    code, err = run_cli(["replay", str(resumed), "--check"], LIMIT_S)
    assert code == 2, err
    assert "frame 43 is not the next multiple of hash_every 10 after frame 0" in err, err


def test_a_resumed_run_s_end_stays_within_its_hashes(resumed: Path) -> None:
    text = resumed.read_text()
    end = next(line for line in text.splitlines() if '"type":"end"' in line)
    assert re.search(r'"frames":6\d,', end), end  # within 60's hash
    resumed.write_text(text.replace(end, re.sub(r'"frames":6\d,', '"frames":90,', end)))
    code, err = run_cli(["replay", str(resumed), "--check"], LIMIT_S)
    assert code == 2, err
    assert "end record: 90 frames" in err, err
