from __future__ import annotations

import hashlib
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.protocols.link import (
    LineSettings,
    Recorder,
    Recording,
    RecordingError,
    ReplayEndpoint,
    SerialLine,
    read_recording,
    replay_into,
)
from camlab88.protocols.link.recording import format_time, parse_recording, parse_time
from tests.support.refusals import refusal_of

CT = Fraction(1, 960)


class HashingDevice:
    """A fake device: hashes every byte it receives with its arrival time and the poll time;
    answers '?' with '!', and sends XOFF when 20 unprocessed bytes pile up (XON when done)."""

    def __init__(self) -> None:
        self.h = hashlib.sha256()
        self.runs: list[tuple[Fraction, bytes]] = []
        self.backlog = 0
        self.stopped = False

    def poll(self, end, now: Fraction) -> None:
        for t, data in end.read_timed(exact=True):
            self.runs.append((t, data))
            for i, b in enumerate(data):  # every byte with its own arrival time
                self.h.update(f"{t - (len(data) - 1 - i) * CT}|{now}|{b};".encode())
            self.backlog += len(data)
            if data.count(b"?"):
                end.write(b"!" * data.count(b"?"))
        if self.backlog >= 20 and not self.stopped:
            end.write(b"\x13")
            self.stopped = True
        elif self.stopped:
            end.write(b"\x11")
            self.stopped = False
        self.backlog = max(0, self.backlog - 5)  # "processing" 5 bytes per poll


def polled_device(end, clock) -> HashingDevice:
    """A fresh device polling ``end`` every 1/100 s for the session's 60 steps, ``clock``
    moved to each poll's time first."""
    device = HashingDevice()
    for step in range(60):
        now = Fraction(step, 100)
        clock.advance_to(now)
        device.poll(end, now)
    return device


def host_program(line: SerialLine, step: int) -> None:
    if step % 3 == 0:
        line.host.write(b"+-*/" + bytes(range(40, 40 + step % 50)) + b"?")
    if step == 7:
        line.host.write(b"late", at=line.clock.exact + Fraction(1, 100))


def run_session(recorder: Recorder | None) -> tuple[str, SerialLine]:
    line = SerialLine(recorder=recorder)
    device = HashingDevice()
    for step in range(60):
        now = Fraction(step, 100)
        line.clock.advance_to(now)
        host_program(line, step)
        device.poll(line.device, now)
        line.host.read()  # the host takes the answers
    line.close()
    return device.h.hexdigest(), line


def test_record_then_replay_is_bit_identical(tmp_path: Path) -> None:
    path = tmp_path / "session.rec"
    original, line = run_session(Recorder(path, LineSettings()))
    assert line.stats["device_to_host_flow"] > 0  # the session really used XON/XOFF
    rec = read_recording(path)
    assert rec.settings == LineSettings() and rec.xonxoff
    assert {d for _, d, _ in rec.entries} == {">", "<"}

    # 1. the recording fed into a fresh line, with a fresh device answering live
    line2 = SerialLine()
    replay_into(rec, line2.host)
    device2 = polled_device(line2.device, line2.clock)
    assert device2.h.hexdigest() == original

    # 2. the recording as an endpoint the device reads directly
    end = ReplayEndpoint(rec, ">")
    device3 = polled_device(end, end.clock)
    assert device3.h.hexdigest() == original
    assert device3.runs == device2.runs  # even the grouping into runs is the same


def test_a_different_session_gives_a_different_hash(tmp_path: Path) -> None:
    original, _ = run_session(None)
    rec_path = tmp_path / "s.rec"
    run_session(Recorder(rec_path, LineSettings()))
    rec = read_recording(rec_path)
    # shift the whole recording by one character time: same bytes, different times
    shifted = Recording(
        rec.settings, [(e.t + CT, e.direction, e.data) for e in rec.exact_entries], rec.xonxoff
    )
    end = ReplayEndpoint(shifted, ">")
    assert polled_device(end, end.clock).h.hexdigest() != original


def test_stream_and_round_trip_of_every_byte_value(tmp_path: Path) -> None:
    path = tmp_path / "all.rec"
    line = SerialLine(LineSettings.parse("1200 8E2"), recorder=Recorder(
        path, LineSettings.parse("1200 8E2")
    ))
    line.host.write(bytes(range(256)))
    line.device.write(b"up")
    line.close()
    rec = read_recording(path)
    assert rec.stream(">", raw=True) == bytes(range(256))
    assert rec.stream(">") == bytes(b for b in range(256) if b not in (0x11, 0x13))
    assert rec.stream("<") == b"up"
    downs = [e for e in rec.exact_entries if e.direction == ">"]
    assert len(downs) == 1  # pieces committed separately were merged: one back-to-back chunk
    assert downs[0].t == 256 * Fraction(12, 1200)
    text = path.read_text()
    assert text.startswith("camlab88-link-recording 1\nline 1200 8E2\nxonxoff on\n")
    assert text.endswith(f"end {len(rec.entries)}\n")


def test_recorder_is_atomic(tmp_path: Path) -> None:
    path = tmp_path / "x.rec"
    rec = Recorder(path, LineSettings())
    rec.record(Fraction(1, 960), ">", b"a")
    assert not path.exists()  # nothing visible until close
    rec.close()
    assert path.exists() and [p.name for p in tmp_path.iterdir()] == ["x.rec"]
    aborted = Recorder(tmp_path / "y.rec", LineSettings())
    aborted.abort()
    assert [p.name for p in tmp_path.iterdir()] == ["x.rec"]


def test_line_refuses_a_recorder_for_other_settings(tmp_path: Path) -> None:
    rec = Recorder(tmp_path / "z.rec", LineSettings(baud=1200))
    with pytest.raises(ValueError, match="1200"):
        SerialLine(LineSettings(), recorder=rec)
    rec.abort()


@pytest.mark.parametrize(
    ("t", "text"),
    [
        (Fraction(1, 25), "0.040000"),
        (Fraction(1, 960), "1/960"),
        (Fraction(3), "3.000000"),
        (Fraction(1, 2**10), "0.0009765625"),
    ],
)
def test_time_format_is_exact(t: Fraction, text: str) -> None:
    assert format_time(t) == text
    assert parse_time(text) == t


@settings(max_examples=200, deadline=None)
@given(st.fractions(min_value=0, max_value=10**6, max_denominator=10**5))
def test_time_format_round_trips(t: Fraction) -> None:
    assert parse_time(format_time(t)) == t


GOOD = "camlab88-link-recording 1\nline 9600 8N1\nxonxoff on\n1/960 > 41\n0.5 < 4243\nend 2\n"


def test_good_text_parses() -> None:
    rec = parse_recording(GOOD, "good.rec")
    assert rec.entries == [(1 / 960, ">", b"A"), (0.5, "<", b"BC")]


@pytest.mark.parametrize(
    ("text", "lineno", "message"),
    [
        ("", 1, "not a camlab88 link recording"),
        ("camlab88-link-recording 9\n", 1, "unsupported recording version"),
        (GOOD.replace("line 9600 8N1\n", ""), 3, "before the 'line"),
        (GOOD.replace("8N1", "8X1"), 2, "bad line settings"),
        (GOOD.replace("1/960 >", "1/0 >"), 4, "bad time"),
        (GOOD.replace("1/960 >", "-1 >"), 4, "bad time"),
        (GOOD.replace("> 41", "> 4"), 4, "bad hex"),
        (GOOD.replace("> 41", "> zz"), 4, "bad hex"),
        (GOOD.replace("> 41", "x 41"), 4, "direction"),
        (GOOD.replace("1/960 > 41", "1/960 > 4142"), 4, "cannot have arrived"),
        (GOOD.replace("0.5 < 4243", "0.5 > 4243\n0.5 > 44"), 6, "overlaps"),
        (GOOD.replace("end 2\n", ""), 6, "truncated"),
        (GOOD.replace("end 2", "end 3"), 6, "says 3 chunks"),
        (GOOD + "1 > 41\n", 7, "after the 'end'"),
        (GOOD.replace("xonxoff on", "xonxoff maybe"), 3, "xonxoff"),
        (GOOD.replace("0.5 < 4243", "0.5 <"), 5, "expected '<time>"),
    ],
)
def test_bad_recordings_name_file_and_line(text: str, lineno: int, message: str) -> None:
    with pytest.raises(RecordingError, match=message) as info:
        parse_recording(text, "bad.rec")
    assert str(info.value).startswith(f"bad.rec:{lineno}:")


def test_read_recording_names_the_file(tmp_path: Path) -> None:
    path = tmp_path / "cut.rec"
    path.write_text(GOOD[: GOOD.index("0.5")])  # truncated mid-file
    with pytest.raises(RecordingError, match=rf"{path}:\d+: truncated"):
        read_recording(path)
    path.write_bytes(GOOD.encode().replace(b"0.5", b"\xff.5"))
    with pytest.raises(RecordingError, match=r"cut.rec:5:1: byte 0xff is not UTF-8"):
        read_recording(path)
    with pytest.raises(RecordingError, match="cannot read"):
        read_recording(tmp_path / "missing.rec")


@settings(max_examples=300, deadline=None)
@given(
    st.text(max_size=300)
    | st.lists(
        st.sampled_from(["1/960", "0.5", "2", "x", ">", "<", "41", "4", "end", "1", "line", "#"])
        | st.text(max_size=5),
        max_size=12,
    ).map(lambda words: " ".join(words).replace("# ", "\n"))
)
def test_parser_never_fails_any_other_way(text: str) -> None:
    refusal_of(parse_recording, "camlab88-link-recording 1\nline 9600 8N1\n" + text, "fuzz.rec",
               RecordingError)


@settings(max_examples=200, deadline=None)
@given(st.integers(0, len(GOOD)), st.integers(0, 255))
def test_mutated_recordings_parse_or_fail_cleanly(pos: int, value: int) -> None:
    raw = bytearray(GOOD.encode())
    if pos < len(raw):
        raw[pos] = value
    else:
        raw = raw[: value % len(raw)]  # truncated
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        return
    refusal_of(parse_recording, text, "m.rec", RecordingError)


def test_the_example_in_docs_link_md_parses() -> None:
    doc = (Path(__file__).resolve().parents[2] / "docs" / "link.md").read_text()
    block = doc.split("## Recording format", 1)[1].split("```", 2)[1]
    rec = parse_recording(block.strip() + "\n", "docs/link.md")
    assert [e.t for e in rec.exact_entries] == [Fraction(1, 80), Fraction(1, 25), Fraction(53, 960)]
    assert rec.stream(">") == b"\r+-*/HH\0\0\0\0\0GH"
