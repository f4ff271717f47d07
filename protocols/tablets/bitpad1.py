"""Summagraphics Bit Pad One as the PERQ used it: ``XXXX,YYYY,F<LF>`` (facts §2.4).

Digits 0000-2200, origin lower-left, no report while the puck is off the tablet.  The flag
character is PERQemu's table ``0213856749ABCDEF`` indexed by the four-button state (read here
as a bitmask -- reconstruction; PERQemu indexes it by button number).
"""

from __future__ import annotations

from camlab88.protocols.tablets.ascii_line import AsciiReportParser, apply_parity, bit_pad_model
from camlab88.protocols.tablets.base import ProtocolError, TabletEncoder
from camlab88.protocols.tablets.events import TabletEvent, TabletModel

NAME = "bitpad1"
DEFAULT_MODEL = bit_pad_model("Summagraphics Bit Pad One")
FLAGS = "0213856749ABCDEF"


class Bitpad1Parser(AsciiReportParser):
    name = NAME
    default_model = DEFAULT_MODEL
    default_parity = "N"
    terminators = b"\n\r"
    flags = FLAGS

    @staticmethod
    def flag_state(flag: str) -> tuple[bool, int]:
        return True, FLAGS.index(flag)


class Bitpad1Encoder(TabletEncoder):
    name = NAME
    xy_max = 9999

    def __init__(self, model: TabletModel = DEFAULT_MODEL, *, parity: str = "N") -> None:
        super().__init__(model)
        self.parity = parity
        self.streaming = True

    def encode(self, event: TabletEvent) -> bytes:
        if not event.proximity:
            return b""  # the Bit Pad One is silent off the tablet
        x, y = self.checked_xy(event)
        if not 0 <= event.buttons < 16:
            raise ProtocolError(f"buttons {event.buttons:#x} outside the 4-button puck")
        text = f"{x:04d},{y:04d},{FLAGS[event.buttons]}\n"
        return apply_parity(text.encode("ascii"), self.parity)
