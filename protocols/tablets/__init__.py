"""Graphics tablets: serial protocol parsers/encoders, USB HID decoding, sources, input layer.

Protocols: ``wacom4`` (Wacom IV), ``summa-mm`` (Summagraphics MM binary, 7-byte Flair with
``flair=1``), ``bitpad1``, ``bitpad2`` (Summagraphics ASCII), ``calcomp`` (DrawingBoard).
"""

from __future__ import annotations

from camlab88.protocols.tablets.events import DeviceReply, TabletEvent, TabletModel
from camlab88.protocols.tablets.registry import PROTOCOL_NAMES, make_encoder, make_parser

__all__ = [
    "PROTOCOL_NAMES",
    "DeviceReply",
    "TabletEvent",
    "TabletModel",
    "make_encoder",
    "make_parser",
]
