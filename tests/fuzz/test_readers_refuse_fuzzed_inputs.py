"""Inputs the fuzz targets (or probes beside them) found that once escaped their reader
with another exception or took unbounded time: each must now be the format's own error,
naming the file, line and column, quickly."""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

import pytest

from camlab88.apps.kas.paint import opsfile
from camlab88.protocols.session import SessionFileError
from camlab88.protocols.session.format import loads
from fuzz.engine import run_one
from fuzz.targets import CORPUS, TARGETS

SESSION = (CORPUS / "session-recording" / "every_record.session").read_bytes()
OPS = (CORPUS / "kas-paint-ops" / "touch_up.ops").read_text()


@pytest.mark.parametrize("old, new, where", [
    # a 5000-digit tick: json's int() raised a bare ValueError (no file, line or column)
    (b'"tick":3,', b'"tick":' + b"1" * 5000 + b",", "<s>:3:1: not JSON"),
    # Fraction('1e99999999999') computes 10**99999999999: no answer, memory without bound
    (b'"time":"3/25"', b'"time":"1e99999999999"', "<s>:3:1: time '1e99999999999'"),
    (b'"tick":3,', b'"tick":10000000000000000,', "<s>:3:1: event record: tick"),
])
def test_damaged_session_recording_gets_the_format_error(old: bytes, new: bytes,
                                                         where: str) -> None:
    assert old in SESSION
    # under the fuzz engine's alarm first, so a hang fails instead of hanging the test
    assert run_one(TARGETS["session-recording"], SESSION.replace(old, new, 1), 5.0) is None
    with pytest.raises(SessionFileError, match=re.escape(where)):
        loads(SESSION.replace(old, new, 1), "<s>")


def test_session_times_the_writer_writes_still_read() -> None:
    # each form (an integer, a fraction, a decimal), no later than the next tick's 4/25: a
    # time that goes back is refused (test_recording_checks.py)
    for t in ("0", "3/25", "0.12", "6/50", "0.1"):
        rec = loads(SESSION.replace(b'"time":"3/25"', f'"time":"{t}"'.encode(), 1), "<s>")
        assert rec.events[0][1] == Fraction(t)


def test_ops_file_huge_number_is_its_own_error(tmp_path: Path) -> None:
    # a 5000-digit 'painted': int() raised a bare ValueError without the file's name
    path = tmp_path / "big.ops"
    path.write_text(OPS.replace("painted 1", "painted " + "9" * 5000))
    with pytest.raises(opsfile.OpsFileError, match=re.escape(f"{path}:7:9: painted frame")):
        opsfile.load(path)


def test_ops_file_errors_quote_a_long_word_shortened() -> None:
    with pytest.raises(opsfile.OpsFileError) as exc:
        opsfile.parse(OPS.replace("gap 0.05", "gap " + "x" * 10**6), "a.ops")
    assert str(exc.value).startswith("a.ops:6:5: gap must be a number") and \
        len(str(exc.value)) < 200


@pytest.mark.parametrize("line", ["1e99999999999999999999999", "1e99999999999 wait",
                                  "+1e99999999999 move 0 0"])
def test_kas_script_time_with_a_huge_exponent_is_refused(line: str) -> None:
    # the long fuzz (kas-script, seed 7): Fraction('1e99999...') ran past the 20 s alarm
    from camlab88.apps.kas.events import parse_script
    from camlab88.apps.kas.files import KasFileError
    from camlab88.apps.kas.program.script import parse_timed_script

    data = (line + "\n").encode()
    assert run_one(TARGETS["kas-script"], data, 5.0) is None
    for parse in (parse_timed_script, parse_script):  # the one KAS script format, both readers
        with pytest.raises(KasFileError, match=re.escape("s.txt:1: bad event")):
            parse(line, "s.txt")


def test_kas_script_times_in_the_documented_shapes_still_read() -> None:
    from camlab88.apps.kas.program.script import parse_timed_script

    events = parse_timed_script("2.5 wait\n+0.1 wait\n3 wait\n.5e1 wait\n1e2 wait\n", "s.txt")
    assert [e.t for e in events] == [Fraction(5, 2), Fraction(13, 5), 3, 5, 100]


@pytest.mark.parametrize("key, value", [("length_m", 1e20), ("middle_mouth_m", 1e-300)])
def test_snooker_session_table_too_large_for_its_pockets_is_refused(key: str,
                                                                    value: float) -> None:
    # the fuzz (snooker-session, seed 7): length_m 1e+20 made a middle pocket's mouth round to
    # zero width in floats, and Table.pockets divided by it (ZeroDivisionError)
    import json

    from camlab88.apps.snooker.session import SessionError

    session = json.loads((CORPUS / "snooker-session" / "new.json").read_text())
    session["table"][key] = value
    data = json.dumps(session).encode()
    assert run_one(TARGETS["snooker-session"], data, 5.0) is None
    with pytest.raises((SessionError, ValueError), match=f"{key}=.* out of range"):
        TARGETS["snooker-session"].run(data)
