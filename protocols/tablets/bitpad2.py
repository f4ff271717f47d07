"""Summagraphics Bit Pad Two (MM1103) ASCII BCD format: ``XXXX,YYYY,F<CR>[<LF>]``.

From the GTCO Bit Pad Two Users Guide (facts §2.3): 7 data bits with optional parity, flag
``9`` = out-of-proximity report (which repeats the last valid coordinate), 11" square active
area at 200 lpi factory default.  The mapping of flag digits 1-8 to cursor buttons ("1234"
cursor data) is a reconstruction: button n pressed -> digit n, none -> 0.
"""

from __future__ import annotations

import re

from protocols.tablets.ascii_line import AsciiReportParser, apply_parity
from protocols.tablets.base import ProtocolError, TabletEncoder, clamp_check
from protocols.tablets.events import DeviceReply, TabletEvent, TabletModel

NAME = "bitpad2"
DEFAULT_MODEL = TabletModel("Summagraphics Bit Pad Two (MM1103)", 2200, 2200, 200.0, None, None,
                            origin="lower-left")
# The Send Configuration reply is "MM1103 BIT PAD II by Summagraphics Version n.n<CR>[<LF>]"
# (manual p.27).  Its command letter is not recovered, so we never ask, but a tablet that sends
# it (e.g. after a front-panel request) yields a DeviceReply rather than a bad report.
CONFIG_PREFIX = "MM1103 BIT PAD II"
_LINE = re.compile(r"(\d{4}),(\d{4}),([0-9])")


def _decoder(tool: str):
    def decode(text: str, timestamp: float) -> TabletEvent:
        match = _LINE.fullmatch(text)
        if match is None:
            raise ValueError(f"not a Bit Pad Two report: {text!r}")
        x, y, flag = int(match.group(1)), int(match.group(2)), int(match.group(3))
        if flag == 9:
            return TabletEvent(x, y, False, 0, None, None, None, tool, timestamp)
        buttons = 0 if flag == 0 else 1 << (flag - 1)
        return TabletEvent(x, y, True, buttons, None, None, None, tool, timestamp)

    return decode


class Bitpad2Parser(AsciiReportParser):
    name = NAME
    default_model = DEFAULT_MODEL
    default_parity = "E"
    terminators = b"\r\n"
    line_decoder = staticmethod(_decoder)

    def _finish(self, line: bytes, timestamp: float) -> TabletEvent | None:
        if line.startswith(CONFIG_PREFIX.encode("ascii")):
            self._replies.append(DeviceReply(line.decode("ascii", "replace"), timestamp))
            self.stats.replies += 1
            return None
        return super()._finish(line, timestamp)


class Bitpad2Encoder(TabletEncoder):
    name = NAME

    def __init__(
        self, model: TabletModel = DEFAULT_MODEL, *, parity: str = "E", linefeed: bool = True
    ) -> None:
        super().__init__(model)
        self.parity = parity
        self.linefeed = linefeed
        self.streaming = True

    def encode(self, event: TabletEvent) -> bytes:
        x = clamp_check(event.x, 0, 9999, "X")
        y = clamp_check(event.y, 0, 9999, "Y")
        if not event.proximity:
            flag = 9
        else:
            b = clamp_check(event.buttons, 0, 0x80, "buttons")
            if b & (b - 1):
                raise ProtocolError(f"one button at a time in the BCD flag, not {b:#x}")
            flag = b.bit_length()
        end = "\r\n" if self.linefeed else "\r"
        return apply_parity(f"{x:04d},{y:04d},{flag}{end}".encode("ascii"), self.parity)

    def split_commands(self, data: bytes) -> tuple[list[bytes], bytes]:
        return [bytes((b & 0x7F,)) for b in data], b""

    def answer(self, command: bytes) -> bytes:
        # Start/Stop transmission are the XON/XOFF equivalents (manual p.27).
        if command == b"\x13":
            self.streaming = False
        elif command == b"\x11":
            self.streaming = True
        return b""
