"""Summagraphics Bit Pad One as the PERQ used it: ``XXXX,YYYY,F<LF>`` (facts §2.4).

Digits 0000-2200, origin lower-left, no report while the puck is off the tablet.  The flag
character is PERQemu's table ``0213856749ABCDEF`` indexed by the four-button state (read here
as a bitmask -- reconstruction; PERQemu indexes it by button number).
"""

from __future__ import annotations

import re

from protocols.tablets.ascii_line import AsciiReportParser, apply_parity
from protocols.tablets.base import ProtocolError, TabletEncoder, clamp_check
from protocols.tablets.events import TabletEvent, TabletModel

NAME = "bitpad1"
DEFAULT_MODEL = TabletModel("Summagraphics Bit Pad One", 2200, 2200, 200.0, None, None,
                            origin="lower-left")
FLAGS = "0213856749ABCDEF"
_LINE = re.compile(r"(\d{4}),(\d{4}),([0-9A-F])")


def _decoder(tool: str):
    def decode(text: str, timestamp: float) -> TabletEvent:
        match = _LINE.fullmatch(text)
        if match is None:
            raise ValueError(f"not a Bit Pad One report: {text!r}")
        buttons = FLAGS.index(match.group(3))
        return TabletEvent(int(match.group(1)), int(match.group(2)), True, buttons, None, None,
                           None, tool, timestamp)

    return decode


class Bitpad1Parser(AsciiReportParser):
    name = NAME
    default_model = DEFAULT_MODEL
    default_parity = "N"
    terminators = b"\n\r"
    line_decoder = staticmethod(_decoder)


class Bitpad1Encoder(TabletEncoder):
    name = NAME

    def __init__(self, model: TabletModel = DEFAULT_MODEL, *, parity: str = "N") -> None:
        super().__init__(model)
        self.parity = parity
        self.streaming = True

    def encode(self, event: TabletEvent) -> bytes:
        if not event.proximity:
            return b""  # the Bit Pad One is silent off the tablet
        x = clamp_check(event.x, 0, 9999, "X")
        y = clamp_check(event.y, 0, 9999, "Y")
        if not 0 <= event.buttons < 16:
            raise ProtocolError(f"buttons {event.buttons:#x} outside the 4-button puck")
        text = f"{x:04d},{y:04d},{FLAGS[event.buttons]}\n"
        return apply_parity(text.encode("ascii"), self.parity)
