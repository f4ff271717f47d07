"""0x11 and 0x13 in a tablet's reports are data: no serial protocol loses them to XON/XOFF.

Every protocol's source is opened on one end of a socat null modem (two real ptys, a tty
driver on each side, as a USB-serial adapter has); the other end is the "tablet" and writes
reports whose bytes include DC1 (0x11) and DC3 (0x13).  With IXON set the host's tty driver
swallows those bytes and the reports are lost (issue 42: 25 of 200 Summagraphics frames).
ASCII protocols (the Bit Pads) cannot put those bytes in a report, so there they come as
a line of noise between reports, which must not spoil the reports after them.  Last comes a
lone XOFF: with IXON it would also stop everything the host sends to the tablet, so the host
then writes a byte and the tablet end must receive it.
"""

from __future__ import annotations

import os
import select
import termios
import time
import tty
from pathlib import Path

import pytest

from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.line_setup import SETUPS
from camlab88.protocols.tablets.registry import PROTOCOL_NAMES, make_encoder
from camlab88.protocols.tablets.serial_source import SerialSource
from camlab88.protocols.tablets.sources import parse_source
from tests.support.serial_servers import null_modem
from tests.tablets.helpers import HANG_GUARD

FLOW = (0x11, 0x13)
TOOL = {"bitpad1": "puck", "bitpad2": "puck", "calcomp": "puck"}
BINARY = ("wacom4", "summa-mm", "calcomp")


def _sweep(protocol: str) -> list[TabletEvent]:
    """Reports of a uniform sweep whose encodings carry 0x11 or 0x13, both kinds present."""
    enc = make_encoder(protocol)
    tool = TOOL.get(protocol, "pen")
    picked: list[TabletEvent] = []
    for x in range(0, 4096, 7):
        event = TabletEvent(x, 4095 - x, True, 1, 100 if protocol == "wacom4" else None,
                            tool=tool)
        if any(b in FLOW for b in enc.encode(event)):
            picked.append(event)
    return picked


@pytest.mark.parametrize("protocol", PROTOCOL_NAMES)
def test_dc1_dc3_bytes_reach_the_parser_through_a_null_modem(tmp_path: Path,
                                                             protocol: str) -> None:
    assert not SETUPS[protocol].describe().endswith("XON/XOFF")
    enc = make_encoder(protocol)
    if protocol in BINARY:
        events = _sweep(protocol)
        data = [enc.encode(e) for e in events]
        assert any(0x11 in d for d in data) and any(0x13 in d for d in data)
    else:  # ASCII reports: the flow bytes come between them
        events = [TabletEvent(100 * k, 50 * k, True, k % 2, tool=TOOL[protocol])
                  for k in range(1, 41)]
        data = [bytes(FLOW) + b"\r\n" + enc.encode(e) for e in events]
    assert len(events) >= 20
    with null_modem(tmp_path) as ends:
        if isinstance(ends, str):
            pytest.skip(ends)
        host_end, tablet_end = ends
        tablet = os.open(tablet_end, os.O_RDWR | os.O_NOCTTY)
        try:
            tty.setraw(tablet)
            attrs = termios.tcgetattr(tablet)
            attrs[0] &= ~(termios.IXON | termios.IXOFF)  # the tablet end sends every byte
            termios.tcsetattr(tablet, termios.TCSANOW, attrs)
            source = SerialSource(parse_source(f"serial:{host_end}?protocol={protocol}&init=0"))
            try:
                got: list[TabletEvent] = []
                os.write(tablet, b"".join(data) + b"\x13")
                deadline = time.monotonic() + HANG_GUARD
                while len(got) < len(events) and time.monotonic() < deadline:
                    got += source.read(timeout=0.05)
                source.read(timeout=0.2)  # the lone XOFF has arrived
                source.write(b"?")
                answer = b""
                while not answer and time.monotonic() < deadline + HANG_GUARD:
                    if select.select([tablet], [], [], 0.05)[0]:
                        answer = os.read(tablet, 16)
            finally:
                source.close()
        finally:
            os.close(tablet)
    assert got == events
    assert answer == b"?"  # the host's output was not stopped by the XOFF


def test_only_the_summagraphics_line_lets_the_host_send_xoff(tmp_path: Path) -> None:
    """IXOFF where the protocol uses it (Summagraphics "FlowControl Xoff"); IXON nowhere."""
    with null_modem(tmp_path) as ends:
        if isinstance(ends, str):
            pytest.skip(ends)
        host_end, _ = ends
        for protocol in PROTOCOL_NAMES:
            source = SerialSource(parse_source(f"serial:{host_end}?protocol={protocol}&init=0"))
            try:
                iflag = termios.tcgetattr(source.port.fileno())[0]
            finally:
                source.close()
            assert not iflag & termios.IXON, protocol
            assert bool(iflag & termios.IXOFF) == (protocol == "summa-mm"), protocol
