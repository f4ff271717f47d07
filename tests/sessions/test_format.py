"""The session recording format: round trip, and damaged input refused with file, line and
column — never another exception (hypothesis)."""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.protocols.session import ScreenHash, SessionFileError, SessionRecording
from camlab88.protocols.session.format import dumps, loads

DATA = Path(__file__).resolve().parents[1] / "data" / "sessions"
GOOD = (DATA / "sigma_run.session").read_bytes()
WHERE = re.compile(r"^<s>:\d+:\d+: ")


def _sample() -> SessionRecording:
    rec = SessionRecording(["ca", "program", "--events", "e.events"], 10, False,
                           {"e.events": b"move 1 2\nwait 3\n"})
    rec.events = [(3, Fraction(3, 50), {"kind": "KeyDown", "key": "a", "char": "a",
                                        "mods": []})]
    rec.wire = [(4, "+", b"\x1b\x00abc"), (10, ">", bytes(range(256)))]
    rec.hashes = [ScreenHash(10, 10, Fraction(1, 5), "ab" * 32)]
    rec.end = ScreenHash(12, 12, Fraction(6, 25), "cd" * 32)
    rec.ticks = 12
    return rec


def test_round_trip() -> None:
    rec = _sample()
    assert loads(dumps(rec).encode(), "<s>") == rec


@pytest.mark.parametrize("text, message", [
    ('{"type":"header","format":"other","version":1,"argv":["x"],"headless":true,'
     '"hash_every":1}', "<s>:1:1: not a camlab88 session recording"),
    ('{"type":"header","format":"camlab88-session","version":2,"argv":["x"],'
     '"headless":true,"hash_every":1}', "newer camlab88 (format version 2)"),
    ('{"type":"header","format":"camlab88-session","version":1,"argv":["x"],'
     '"headless":true,"hash_every":1}', "<s>:1:1: truncated"),
    ('{"type":"header"', "<s>:1:17: not JSON"),
    ('{"type":"header","format":"camlab88-session","version":3}', "newer camlab88"),
])
def test_refusals_say_where_and_why(text: str, message: str) -> None:
    with pytest.raises(SessionFileError, match=re.escape(message)):
        loads(text.encode(), "<s>")


def test_ticks_going_back_and_bad_hashes_are_refused() -> None:
    lines = dumps(_sample()).splitlines()
    swapped = "\n".join(lines[:2] + [lines[3], lines[2]] + lines[4:]).encode()
    with pytest.raises(SessionFileError, match="goes back"):
        loads(swapped, "<s>")
    with pytest.raises(SessionFileError, match="does not match its sha256"):
        loads(dumps(_sample()).replace('"sha256":"', '"sha256":"0', 1).encode(), "<s>")


@settings(max_examples=200, deadline=None)
@given(st.integers(0, len(GOOD)), st.binary(max_size=8), st.integers(0, 8))
def test_damaged_recordings_are_refused_cleanly(at: int, junk: bytes, cut: int) -> None:
    damaged = GOOD[:at] + junk + GOOD[at + cut:]
    try:
        loads(damaged, "<s>")
    except SessionFileError as exc:
        assert WHERE.match(str(exc)), str(exc)


@settings(max_examples=200, deadline=None)
@given(st.binary(max_size=300))
def test_arbitrary_bytes_are_refused_cleanly(data: bytes) -> None:
    with pytest.raises(SessionFileError) as exc:
        loads(data, "<s>")
    assert WHERE.match(str(exc.value))
