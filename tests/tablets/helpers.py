"""Shared helpers: a real pty pair opened with pyserial, and capture-file loaders."""

from __future__ import annotations

import time
from pathlib import Path

import serial

from camlab88.protocols.link.pty import PtyPort
from camlab88.protocols.tablets.base import TabletParser
from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.hid_descriptor import (
    ReportDescriptor,
    parse_descriptor,
    parse_hex_text,
)

DATA = Path(__file__).resolve().parents[1] / "data" / "tablets"
DIGIMEND = DATA / "digimend-tablets"
SELFTESTS = DATA / "linux-hid-selftests"
HANG_GUARD = 5.0  # seconds before a read loop gives up (a guard against hangs, not a timing test)


class PtyPair:
    """Master side (the "tablet") and a pyserial port on the slave side (the "host")."""

    def __init__(self) -> None:
        self.master = PtyPort()
        self.host = serial.Serial(self.master.slave_path, 9600, timeout=0)

    def send(self, data: bytes) -> None:
        self.master.write(data)
        while self.master.backlog:
            self.master.flush()

    def receive(self, n: int) -> bytes:
        """Exactly n bytes from the host side (or fewer if the guard expires)."""
        got = bytearray()
        deadline = time.monotonic() + HANG_GUARD
        while len(got) < n and time.monotonic() < deadline:
            chunk = self.host.read(n - len(got))
            if chunk:
                got += chunk
            else:
                time.sleep(0.001)
        return bytes(got)

    def through(self, parser: TabletParser, data: bytes) -> list[TabletEvent]:
        """Write ``data`` as the tablet, read it with pyserial, parse it."""
        self.send(data)
        return parser.feed(self.receive(len(data)))

    def close(self) -> None:
        self.host.close()
        self.master.close()


def load_descriptor(path: Path) -> ReportDescriptor:
    return parse_descriptor(parse_hex_text(path.read_text(), str(path)), str(path))


def load_dump(path: Path) -> list[bytes]:
    """usbhid-dump stream records: header line with ':' then one line of hex."""
    reports = []
    for line in path.read_text().splitlines():
        line = line.strip()
        if line and ":" not in line:
            reports.append(bytes.fromhex(line))
    return reports
