"""Nothing attached, or the wrong thing: every case ends within 10 s with a message naming the
device and the next step; nothing is printed as found when it is not."""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import pytest

from camlab88.protocols.link.pty import PtyPort
from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.registry import make_encoder
from tests.support.serial_servers import null_modem

LIMIT = 10.0


def _camlab88(args: list[str], **kw) -> tuple[subprocess.CompletedProcess[str], float]:
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "camlab88", *args], capture_output=True,
                          text=True, timeout=60, **kw)
    return done, time.monotonic() - start


@pytest.mark.parametrize("protocol", ["wacom4", "summa-mm", "calcomp"])
def test_a_serial_tablet_that_does_not_answer_is_not_reported_as_found(protocol: str) -> None:
    silent = PtyPort()  # a port with nothing on the other end: nobody ever answers
    try:
        source = f"serial:{silent.slave_path}?protocol={protocol}"
        done, took = _camlab88(["tablet", "monitor", source])
    finally:
        silent.close()
    assert took < LIMIT
    assert done.returncode == 2
    assert done.stdout == ""  # no "# ...: Wacom UD (protocol IV), 0..15240" header
    err = done.stderr
    assert source in err and "no answer from a tablet" in err
    assert "check the cable" in err and "protocol" in err and "baud" in err


def test_calibrate_gives_up_with_a_hint_when_nothing_comes() -> None:
    silent = PtyPort()
    try:
        source = f"serial:{silent.slave_path}?protocol=bitpad1"  # no start-up query to fail
        done, took = _camlab88(["tablet", "calibrate", source, "--seconds", "2"])
    finally:
        silent.close()
    assert took < LIMIT and done.returncode == 1
    assert "touch the TOP-LEFT corner" in done.stdout
    assert f"{source}: calibration gave up after 2 s: nothing came from the tablet" in \
        done.stderr


def test_calibrate_says_when_bytes_come_but_are_not_reports(tmp_path: Path) -> None:
    with null_modem(tmp_path) as ends:
        if isinstance(ends, str):
            pytest.skip(ends)
        a, b = ends
        import serial

        start = time.monotonic()
        proc = subprocess.Popen([sys.executable, "-m", "camlab88", "tablet", "calibrate",
                                 f"serial:{a}?protocol=bitpad1", "--seconds", "2"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        with serial.Serial(b, 9600) as far:
            assert "touch the TOP-LEFT" in proc.stdout.readline()  # the port is open now
            far.write(b"\x80\x81\x82" * 50)  # not Bit Pad One ASCII
            _out, err = proc.communicate(timeout=LIMIT)
    assert time.monotonic() - start < LIMIT and proc.returncode == 1
    assert "bytes came but none decoded as a report" in err


def test_monitor_keeps_running_when_the_serial_line_closes_and_comes_back(
        tmp_path: Path) -> None:
    """A pty pair closing under the monitor (a USB-serial adapter pulled) and reappearing."""
    import serial

    encode = make_encoder("bitpad1").encode
    before = [TabletEvent(100 + k, 200, True, 0) for k in range(3)]
    after = [TabletEvent(500 + k, 600, True, 1) for k in range(3)]
    start = time.monotonic()
    with null_modem(tmp_path) as ends:
        if isinstance(ends, str):
            pytest.skip(ends)
        a, b = ends
        proc = subprocess.Popen([sys.executable, "-m", "camlab88", "tablet", "monitor",
                                 f"serial:{a}?protocol=bitpad1", "--count", "6"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert proc.stdout.readline().startswith("# serial:")
        with serial.Serial(b, 9600) as far:
            far.write(b"".join(encode(e) for e in before))
            for _ in before:
                assert " x=" in proc.stdout.readline()
    # socat is gone: both ptys closed under the monitor; now the line comes back
    with null_modem(tmp_path) as ends:
        assert not isinstance(ends, str)
        a, b = ends
        with serial.Serial(b, 9600) as far:
            deadline = time.monotonic() + LIMIT
            err = ""
            while "back" not in err and time.monotonic() < deadline:
                far.write(b"".join(encode(e) for e in after))
                time.sleep(0.5)
                if proc.poll() is not None:
                    break
            out, err = proc.communicate(timeout=LIMIT)
    assert time.monotonic() - start < 3 * LIMIT
    assert proc.returncode == 0, err
    assert "lost" in err and "waiting for it to come back" in err and "back" in err
    xs = [int(line.split("x=")[1].split()[0]) for line in out.splitlines() if " x=" in line]
    assert xs[:3] == [500, 501, 502]


def test_monitor_of_a_tablet_without_a_query_says_what_to_check_when_nothing_comes() -> None:
    """A Bit Pad One has no start-up query: an empty port cannot be told from a pen held
    away from the tablet, so the monitor keeps listening but says, once, what to check."""
    silent = PtyPort()
    try:
        source = f"serial:{silent.slave_path}?protocol=bitpad1"
        done, _took = _camlab88(["tablet", "monitor", source, "--seconds", "5.5"])
    finally:
        silent.close()
    assert done.returncode == 0
    assert f"{source}: no report in 5 s; nothing at all came" in done.stderr
    assert "check the cable" in done.stderr and done.stderr.count("no report in") == 1
