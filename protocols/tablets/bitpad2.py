"""Summagraphics Bit Pad Two (MM1103) ASCII BCD format: ``XXXX,YYYY,F<CR>[<LF>]``.

From the GTCO Bit Pad Two Users Guide (facts §2.3): 7 data bits with optional parity, flag
``9`` = out-of-proximity report (which repeats the last valid coordinate), 11" square active
area at 200 lpi factory default.  The mapping of flag digits 1-8 to cursor buttons ("1234"
cursor data) is a reconstruction: button n pressed -> digit n, none -> 0.
"""

from __future__ import annotations

from camlab88.protocols.tablets.ascii_line import AsciiReportParser, apply_parity, bit_pad_model
from camlab88.protocols.tablets.base import ProtocolError, TabletEncoder, clamp_check
from camlab88.protocols.tablets.events import DeviceReply, TabletEvent, TabletModel

NAME = "bitpad2"
DEFAULT_MODEL = bit_pad_model("Summagraphics Bit Pad Two (MM1103)")
# The Send Configuration reply is "MM1103 BIT PAD II by Summagraphics Version n.n<CR>[<LF>]"
# (manual p.27).  Its command letter is not recovered, so we never ask, but a tablet that sends
# it (e.g. after a front-panel request) yields a DeviceReply rather than a bad report.
CONFIG_PREFIX = "MM1103 BIT PAD II"


class Bitpad2Parser(AsciiReportParser):
    name = NAME
    default_model = DEFAULT_MODEL
    default_parity = "E"
    terminators = b"\r\n"
    flags = "0-9"

    @staticmethod
    def flag_state(flag: str) -> tuple[bool, int]:
        """9: out of proximity; n: button n (one at a time); 0: none."""
        n = int(flag)
        return (False, 0) if n == 9 else (True, 0 if n == 0 else 1 << (n - 1))

    def _finish(self, line: bytes, timestamp: float) -> TabletEvent | None:
        if line.startswith(CONFIG_PREFIX.encode("ascii")):
            self._replies.append(DeviceReply(line.decode("ascii", "replace"), timestamp))
            self.stats.replies += 1
            return None
        return super()._finish(line, timestamp)


class Bitpad2Encoder(TabletEncoder):
    name = NAME
    xy_max = 9999

    def __init__(
        self, model: TabletModel = DEFAULT_MODEL, *, parity: str = "E", linefeed: bool = True
    ) -> None:
        super().__init__(model)
        self.parity = parity
        self.linefeed = linefeed
        self.streaming = True

    def encode(self, event: TabletEvent) -> bytes:
        x, y = self.checked_xy(event)
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
