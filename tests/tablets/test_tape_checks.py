"""A tablet tape in a session recording is checked like every other record, by the reader:
each entry's poll, kind and payload type, and its depth — a damaged ``T`` record is refused
with the recording's file and line, never a TypeError, IndexError or RecursionError later."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from camlab88.protocols.session import SessionFileError, read, write
from camlab88.protocols.session.format import ScreenHash, SessionRecording
from camlab88.protocols.tablets.tape import Tape, TapeError, parse_chunk

GOOD = [[0, "open", {"kind": "serial", "name": "t", "protocol": "summa", "options": {},
                     "model": {}, "replies": [], "parmrk": False}],
        [1, "raw", "00ff"], [2, "flush", None], [3, "idle", 1], [4, "lost", "unplugged"],
        [5, "calibration", {"device": "d", "top_left": [0, 0], "bottom_right": [9, 9]}],
        [6, "calibration", None]]

BAD = {
    "raw payload a number": b'[[0,"raw",5]]',
    "raw payload null": b'[[0,"raw",null]]',
    "raw payload not hex": b'[[0,"raw","zz"]]',
    "idle level 9": b'[[0,"idle",9]]',
    "idle level true": b'[[0,"idle",true]]',
    "nested 100,000 deep": b"[" * 100000 + b"]" * 100000,
    "an unknown kind": b'[[0,"boom",1]]',
    "a poll that is negative": b'[[-1,"flush",null]]',
    "a poll that is a bool": b'[[true,"flush",null]]',
    "a flush with a payload": b'[[0,"flush",[1,2]]]',
    "an opening of another kind": b'[[0,"open",{"kind":"usb"}]]',
    "a serial opening whose options are a list": (
        b'[[0,"open",{"kind":"serial","protocol":"summa","options":[1],"model":{}}]]'),
    "a HID opening with a vid out of range": b'[[0,"open",{"kind":"hid","vid":70000,"pid":1}]]',
    "not a list": b'{"poll":0}',
    "not UTF-8": b'[[0,"lost","\xff"]]',
}


def test_a_good_tape_passes() -> None:
    entries = parse_chunk(json.dumps(GOOD).encode())
    assert Tape(entries).first("calibration")["device"] == "d"


@pytest.mark.parametrize("chunk", BAD.values(), ids=BAD.keys())
def test_a_bad_chunk_is_a_tape_error(chunk: bytes) -> None:
    with pytest.raises(TapeError):
        Tape.from_chunks([chunk])


def _recording(path: Path, chunk: bytes) -> Path:
    rec = SessionRecording(["kas", "edit", "k.kas"], hash_every=10)
    rec.wire.append((1, "T", json.dumps(GOOD).encode()))
    rec.wire.append((2, "T", chunk))
    rec.end = ScreenHash(0, 3, 0, "0" * 64)
    rec.ticks = 3
    write(path, rec)
    return path


@pytest.mark.parametrize("chunk", BAD.values(), ids=BAD.keys())
def test_the_reader_refuses_a_damaged_tape_with_file_and_line(tmp_path: Path,
                                                                chunk: bytes) -> None:
    path = _recording(tmp_path / "r.session", chunk)
    with pytest.raises(SessionFileError) as err:
        read(path)
    message = str(err.value)
    assert message.startswith(f"{path}:3:1: ") and "tablet tape" in message, message
    assert "\n" not in message


def test_the_reader_keeps_a_good_tape(tmp_path: Path) -> None:
    rec = read(_recording(tmp_path / "r.session", json.dumps(GOOD[1:3]).encode()))
    assert [d for _t, d, _data in rec.wire] == ["T", "T"]
