"""Summagraphics MM-series / SummaSketch binary ("MM format", 5 bytes) and the 7-byte Flair.

Layout from the XFree86 ``summa`` driver and gpm (facts §2.1): low 7 bits first, bit 6 of the
first byte set = OUT of proximity.  The three button bits are a code in the X driver and a
bitmask in gpm's ``M_summa``; ``buttons="code"`` (default, the X driver) or ``"mask"``.
"""

from __future__ import annotations

from dataclasses import replace

from camlab88.protocols.tablets.base import (
    ProtocolError,
    SyncFramedParser,
    TabletEncoder,
    clamp_check,
    one_of,
)
from camlab88.protocols.tablets.events import TabletEvent, TabletModel

NAME = "summa-mm"
# SummaSketch 12x12 in MM mode at the default 500 lpi letter ``h`` (facts §2.1).  The start-up
# sequence sends ``b`` (origin upper-left, as the X driver and inputattach's EasyPen init do),
# so that is the origin the host decodes with; the tablet's own power-on origin is lower-left.
DEFAULT_MODEL = TabletModel("Summagraphics MM (SummaSketch 12x12)", 6000, 6000, 500.0, None, None,
                            origin="upper-left")
FLAIR_MODEL = TabletModel("Summagraphics Flair (Z axis)", 6000, 6000, 500.0, 511, None,
                          origin="upper-left")
POWER_ON_ORIGIN = "lower-left"  # reconstructed: Cartesian, like the Bit Pads; ``b`` changes it
SIGN_BITS = 0x18  # X/Y sign bits: absolute mode always sets both (facts §2.1)
FIRMWARE_ID = b"SUMMA MM EMULATION\r"  # reconstructed: the real z? string is not known
# Flair controller type (byte 6 bits 3-2) -> tool
FLAIR_TOOLS = {0: "puck", 1: "pen", 2: "puck"}
RESOLUTION_LETTERS = {
    b"l": 1, b"n": 2, b"p": 4, b"d": 100, b"e": 200, b"f": 254, b"g": 400, b"h": 500,
    b"i": 508, b"j": 1000, b"q": 1016, b"s": 2000, b"u": 2032, b"v": 2540,
}


def _buttons_from_field(value: int, encoding: str) -> int:
    if encoding == "mask":
        return value
    return 0 if value == 0 else 1 << (value - 1)


def _field_from_buttons(buttons: int, encoding: str) -> int:
    if encoding == "mask":
        return clamp_check(buttons, 0, 7, "buttons")
    if buttons == 0:
        return 0
    if buttons & (buttons - 1) or buttons > 0x40:
        raise ProtocolError(f"code encoding carries one button at a time, not {buttons:#x}")
    return buttons.bit_length()


class SummaParser(SyncFramedParser):
    name = NAME
    checks_range = True

    def __init__(
        self,
        model: TabletModel | None = None,
        *,
        flair: bool = False,
        buttons: str = "code",
        tool: str = "pen",
        parmrk: bool = False,
    ) -> None:
        super().__init__(model or (FLAIR_MODEL if flair else DEFAULT_MODEL), parmrk)
        self.button_encoding = one_of("buttons", buttons, ("code", "mask"))
        self.tool = tool
        self.flair = flair
        self._use_framer(7 if flair else 5)

    def decode(self, p: bytes, timestamp: float = 0.0) -> TabletEvent | None:
        if p[0] & SIGN_BITS != SIGN_BITS:  # not an absolute report: noise that looked like sync
            self.stats.bad_packets += 1
            return None
        proximity = not p[0] & 0x40
        x = p[1] | p[2] << 7
        y = p[3] | p[4] << 7
        buttons = _buttons_from_field(p[0] & 7, self.button_encoding)
        pressure = None
        tool = self.tool
        if self.flair:
            pressure = (p[5] & 0x7F) << 2 | (p[6] & 1) << 1 | (p[6] >> 4 & 1)
            tool = FLAIR_TOOLS.get(p[6] >> 2 & 3, self.tool)
        return TabletEvent(x, y, proximity, buttons, pressure, None, None, tool, timestamp)


class SummaEncoder(TabletEncoder):
    """MM-format reports plus the few host commands a SummaSketch answers."""

    name = NAME
    xy_max = 0x3FFF

    def __init__(
        self,
        model: TabletModel | None = None,
        *,
        flair: bool = False,
        buttons: str = "code",
        tablet_id: int = 0,
    ) -> None:
        base = model or (FLAIR_MODEL if flair else DEFAULT_MODEL)
        super().__init__(replace(base, origin=POWER_ON_ORIGIN))
        self.flair = flair
        self.button_encoding = buttons
        self.tablet_id = tablet_id
        self.streaming = True  # factory default: stream mode ("@")
        self.prompted = 0  # reports owed after "P" in prompt mode

    def encode(self, event: TabletEvent) -> bytes:
        x, y = self.checked_xy(event)
        b0 = 0x80 | (0 if event.proximity else 0x40) | (0x20 if self.tablet_id else 0) | 0x18
        b0 |= _field_from_buttons(event.buttons, self.button_encoding)
        packet = bytes((b0, x & 0x7F, x >> 7, y & 0x7F, y >> 7))
        if self.flair:
            z = clamp_check(event.pressure or 0, 0, 511, "pressure")
            kind = {"pen": 1, "eraser": 1, "puck": 0}[event.tool]
            b6 = (z & 1) << 4 | kind << 2 | (1 if event.buttons else 0) << 1 | (z >> 1 & 1)
            packet += bytes((z >> 2, b6))
        return packet

    def config_report(self) -> bytes:
        """Reply to ``a``: a report whose X/Y fields hold the maximum X/Y."""
        mx, my = self.model.max_x, self.model.max_y
        return bytes((0x80 | 0x18, mx & 0x7F, mx >> 7, my & 0x7F, my >> 7))

    def split_commands(self, data: bytes) -> tuple[list[bytes], bytes]:
        commands: list[bytes] = []
        i = 0
        while i < len(data):
            b = data[i : i + 1]
            if b in (b"z", b"I"):  # two-byte commands: "z?", "zb", "I" + chr(32 + n)
                if i + 1 >= len(data):
                    return commands, data[i:]
                commands.append(data[i : i + 2])
                i += 2
                continue
            if b != b" ":  # the spaces sent "in case the tablet can auto-baud" are no-ops
                commands.append(b)
            i += 1
        return commands, b""

    def answer(self, command: bytes) -> bytes:
        if command == b"\x00":  # reset: back to stream mode and the power-on origin
            self.streaming = True
            self.model = replace(self.model, origin=POWER_ON_ORIGIN)
        elif command == b"b":  # origin upper-left
            self.model = replace(self.model, origin="upper-left")
        elif command == b"B":
            self.streaming = False
        elif command == b"@":
            self.streaming = True
        elif command == b"P":
            self.prompted += 1
        elif command == b"a":
            return self.config_report()
        elif command == b"z?":
            return FIRMWARE_ID
        return b""
