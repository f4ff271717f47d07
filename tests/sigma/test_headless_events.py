"""``sigma run --events FILE``: a headless run answers a host's cursor read (issue 42 item 4).

A PGPLOT-style C program (tests/sigma/programs/pgcurs.c: the bytes of PGPLOT's /GOC driver
for PGCURS) draws a page, arms a cursor report and blocks reading 9 bytes; the script moves
the crosshair and strikes a key once the host waits for the reply; the program prints what
it read and ends, and ``--until-idle`` ends the run.  Also the script language's errors.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.protocols.sigma.input_script import InputScriptError, parse

PROGRAM = Path(__file__).parent / "programs" / "pgcurs.c"


@pytest.fixture(scope="module")
def pgcurs(tmp_path_factory: pytest.TempPathFactory) -> str:
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        pytest.skip("no C compiler (cc): .ci/run installs gcc")
    exe = tmp_path_factory.mktemp("pgcurs") / "pgcurs"
    subprocess.run([cc, "-O", "-o", str(exe), str(PROGRAM)], check=True, timeout=120)
    return str(exe)


def test_a_headless_run_answers_the_cursor_read(pgcurs: str, tmp_path: Path) -> None:
    script = tmp_path / "answer.events"
    script.write_text("# PGCURS: when the host waits, move the crosshair and strike A\n"
                      "reply cursor 468 356\nnext key A\n")
    rec = tmp_path / "line.rec"
    run = subprocess.Popen(
        [sys.executable, "-m", "camlab88", "sigma", "run", "--headless", "--pty", "--events",
         str(script), "--until-idle", "1", "--strict", "--record-line", str(rec)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        first = run.stdout.readline()
        assert "on pty" in first, first + run.stderr.read()
        host = subprocess.run([pgcurs, first.split()[-1]], capture_output=True, text=True,
                              timeout=60)
        out, err = run.communicate(timeout=60)
    finally:
        if run.poll() is None:
            run.kill()
            run.wait()
    assert host.returncode == 0, host.stderr
    assert host.stdout == "CURSOR key=A x=468 y=356 end=0d\n"  # what GRGO11 parses
    assert run.returncode == 0, err
    assert "0 unknown and 0 malformed" in out


def test_script_events_and_errors() -> None:
    events = parse("0.5 key A\nreply cursor 10 20   # a comment\nnext tablet 1 2 down\n"
                   "next type HI # kept\n2 key return\n")
    assert [(e.when, e.action) for e in events] == [
        ("at", "key"), ("reply", "cursor"), ("next", "tablet"), ("next", "key"), ("at", "key")]
    assert events[0].at == 0.5 and events[2].down and events[3].text == "HI # kept"
    assert events[4].text == "\r"
    for text, where, words in [
        ("soon key A\n", ":1:1:", "expected a time"),
        ("1 key\n", ":1:3:", "key takes one key"),
        ("1 key enter\n", ":1:7:", "unknown key 'enter'"),
        ("\n1 cursor 10 5000\n", ":2:13:", "coordinate 0..4095"),
        ("1 tablet 1 2 pressed\n", ":1:14:", "up or down"),
        ("1 jump 1 2\n", ":1:3:", "unknown action"),
        ("99999 key A\n", ":1:1:", "expected a time"),
    ]:
        with pytest.raises(InputScriptError) as exc:
            parse(text, "s.events")
        assert str(exc.value).startswith("s.events" + where) and words in str(exc.value), \
            str(exc.value)


def test_a_bad_script_is_refused_before_the_run(tmp_path: Path) -> None:
    script = tmp_path / "bad.events"
    script.write_text("reply cursor 1\n")
    done = subprocess.run([sys.executable, "-m", "camlab88", "sigma", "run", "--headless",
                           "--events", str(script)], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 2
    assert f"{script}:1:7: expected cursor X Y" in done.stderr


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet="0123456789. keytypcursorablnxdwp#\n AZ", max_size=200))
def test_any_script_text_parses_or_fails_with_a_located_error(text: str) -> None:
    try:
        events = parse(text, "f")
    except InputScriptError as exc:
        assert re.match(r"f:\d+:\d+: ", str(exc)), str(exc)
    else:
        assert all(e.when in ("at", "reply", "next") for e in events)
