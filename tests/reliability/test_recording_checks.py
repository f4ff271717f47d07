"""Loose checks of a recording's numbers: an altered tick or time is caught by the replay
(the hash and end records must agree with what it computes), a tick/time pair that cannot
be, or a screen hash at a frame no run reaches, is refused by the reader with file:line, and
a mismatch message never shows two identical hash prefixes."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.emulator.harness.replay import Mismatch
from camlab88.protocols.session import SessionFileError, read

DATA = Path(__file__).resolve().parents[1] / "data" / "sessions"
CA = DATA / "ca_program.session"


def _edited(tmp_path: Path, old: bytes, new: bytes) -> Path:
    raw = CA.read_bytes()
    assert raw.count(old) == 1, old
    path = tmp_path / "edited.session"
    path.write_bytes(raw.replace(old, new))
    return path


@pytest.mark.parametrize(("old", "new"), [
    (b'"frame":50,"tick":50,"time":"1"', b'"frame":50,"tick":51,"time":"1"'),    # a tick
    (b'"frame":50,"tick":50,"time":"1"', b'"frame":50,"tick":50,"time":"21/20"'),  # a time
    (b'"frames":92,"time":"46/25"', b'"frames":92,"time":"47/25"'),                 # the end's
])
def test_an_altered_tick_or_time_fails_the_check(tmp_path: Path, capsys,
                                                 old: bytes, new: bytes) -> None:
    path = _edited(tmp_path, old, new)
    read(path)  # the reader cannot know: the replay must
    assert main(["replay", str(path), "--check", "--headless"]) == 1
    err = capsys.readouterr().err
    assert "differs from the recording" in err and ("tick" in err or "time" in err), err


@pytest.mark.parametrize(("old", "new", "says"), [
    (b'"frame":90,"tick":90', b'"frame":1000000000000,"tick":90', "frame 1000000000000"),
    (b'"frame":90,"tick":90', b'"frame":95,"tick":90', "not the next multiple"),
    (b'"frame":90,"tick":90', b'"frame":80,"tick":90', "not the next multiple"),
    (b'"frames":92,', b'"frames":85,', "stop at frame 90"),
    (b'"frames":92,', b'"frames":1000000000000,', "stop at frame 90"),
    (b'"frame":50,"tick":50,"time":"1"', b'"frame":50,"tick":50,"time":"1/2"', "does not go"),
])
def test_impossible_frames_and_times_are_refused_with_file_and_line(
        tmp_path: Path, capsys, old: bytes, new: bytes, says: str) -> None:
    path = _edited(tmp_path, old, new)
    line = CA.read_bytes()[:CA.read_bytes().index(old)].count(b"\n") + 1
    with pytest.raises(SessionFileError, match=f":{line}:1: .*{says}"):
        read(path)
    assert main(["replay", str(path), "--check", "--headless"]) == 2
    assert f"{path}:{line}:" in capsys.readouterr().err


def test_two_times_for_one_tick_are_refused(tmp_path: Path) -> None:
    lines = CA.read_bytes().decode().splitlines(keepends=True)
    at = next(i for i, t in enumerate(lines) if '"frame":50,"tick":50,"time":"1"' in t)
    event = '{"type":"event","tick":50,"time":"11/10","event":{"kind":"Quit"}}\n'
    path = tmp_path / "twin.session"
    path.write_text("".join([*lines[:at], event, *lines[at:]]))
    with pytest.raises(SessionFileError, match=f":{at + 2}:1: time 1 at tick 50 does not go"):
        read(path)


def test_a_mismatch_shows_hashes_that_differ_where_they_differ() -> None:
    want, got = "0123456789abcdef" * 2 + "a" * 32, "0123456789abcdef" * 2 + "b" * 32
    text = Mismatch(10, 10, Fraction(1, 5), want, got).describe()
    shown = text.split("expected ")[1].split(", got ")
    assert shown[0] != shown[1] and want.startswith(shown[0]) and got.startswith(shown[1])
    far = Mismatch(10, 10, Fraction(1, 5), "1" * 64, "2" * 64).describe()
    assert f"expected {'1' * 16}, got {'2' * 16}" in far


def test_a_missing_screen_hash_is_refused(tmp_path: Path) -> None:
    lines = CA.read_bytes().decode().splitlines(keepends=True)
    at = next(i for i, t in enumerate(lines) if '"frame":50,' in t)
    kept = lines[:at] + lines[at + 1:]
    path = tmp_path / "gap.session"
    path.write_text("".join(kept))
    line = next(i for i, t in enumerate(kept, start=1) if '"frame":60,' in t)
    with pytest.raises(SessionFileError, match=f":{line}:1: hash record: frame 60 is not"):
        read(path)


def test_a_replay_stops_past_the_recorded_end_however_many_ticks_it_claims(
        tmp_path: Path) -> None:
    """A recording claiming 10^12 ticks of a program that would run on (sigma run without
    --seconds) stops one frame past its recorded last frame: bounded by the file."""
    import os
    import subprocess
    import sys

    raw = (DATA / "sigma_run.session").read_bytes()
    raw = raw.replace(b'"--seconds","3"', b'"--model","t5684"').replace(
        b'"ticks":300', b'"ticks":1000000000000')
    path = tmp_path / "long.session"
    path.write_bytes(raw)
    root = Path(__file__).resolve().parents[2]
    done = subprocess.run([sys.executable, "-m", "camlab88", "replay", str(path), "--check",
                           "--headless"], capture_output=True, text=True, timeout=240,
                          env={**os.environ, "PYTHONPATH": str(root)}, check=False)
    assert done.returncode == 1, done.stderr
    assert "the end at frame 76" in done.stderr and "the end at frame 77" in done.stderr
