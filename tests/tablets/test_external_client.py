"""Another process opens the emulated tablet's pty with pyserial and decodes its bytes."""

from __future__ import annotations

import subprocess
import sys
import time

import serial

from camlab88.protocols.tablets.registry import make_parser
from tests.tablets.helpers import HANG_GUARD


def test_outside_program_reads_the_emulated_tablet() -> None:
    proc = subprocess.Popen(
        [sys.executable, "-m", "camlab88", "tablet", "emulate", "--demo", "--seconds", "8"],
        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
    )
    try:
        line = proc.stdout.readline()
        assert line.startswith("serial port: /dev/"), line
        path = line.split()[2]
        port = serial.Serial(path, 9600, parity=serial.PARITY_ODD, timeout=0.05)
        parser = make_parser("summa-mm")
        events = []
        deadline = time.monotonic() + HANG_GUARD
        while len(events) < 20 and time.monotonic() < deadline:
            events += parser.feed(port.read(256))
        port.close()
        assert len(events) >= 20
        assert all(0 <= e.x <= 6000 and 0 <= e.y <= 6000 for e in events)
        assert parser.stats.dropped_bytes < 5  # at most one packet cut by opening mid-stream
    finally:
        proc.terminate()
        proc.wait(timeout=10)
        proc.stdout.close()
