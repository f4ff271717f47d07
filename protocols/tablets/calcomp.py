"""CalComp DrawingBoard binary (6 bytes), checked against a real DrawingBoard 23120 frame.

Layout: hansake's capture (``bc 31 2d 00 2e 0f`` -> X 6317, Y 5903, four buttons) and the
XFree86 ``calcomp`` driver (facts §3).  The drivers disagree on the proximity bit (comment:
byte 3 bit 6; code: 0x20, set = out); ``prox_bit`` chooses, default the code's 0x20.
"""

from __future__ import annotations

from camlab88.protocols.tablets.base import (
    ProtocolError,
    SyncFramedParser,
    TabletEncoder,
    clamp_check,
    one_of,
)
from camlab88.protocols.tablets.events import TabletEvent, TabletModel

NAME = "calcomp"
# DrawingBoard 23120: 0 .. 11999 on both axes (the captured right edge), 1000 lpi (ESC%JR1000,0).
DEFAULT_MODEL = TabletModel("CalComp DrawingBoard 23120", 11999, 11999, 1000.0, None, None,
                            origin="lower-left")
FIRMWARE_ID = b"CALCOMP DRAWINGBOARD EMULATION\r"  # reconstructed


class CalcompParser(SyncFramedParser):
    name = NAME
    checks_range = True

    def __init__(
        self,
        model: TabletModel = DEFAULT_MODEL,
        *,
        prox_bit: int = 0x20,
        tool: str = "puck",
        parmrk: bool = False,
    ) -> None:
        super().__init__(model, parmrk)
        self.prox_bit = one_of("prox_bit", prox_bit, (0, 0x20, 0x40),
                               lambda v: hex(v) if v else "0")
        self.tool = tool
        self._use_framer(6)

    def decode(self, p: bytes, timestamp: float = 0.0) -> TabletEvent:
        buttons = (p[0] & 0x3C) >> 2  # 0x04 button 0 ... 0x20 button 3
        x = (p[0] & 3) << 14 | p[1] << 7 | p[2]
        y = (p[3] & 3) << 14 | p[4] << 7 | p[5]
        proximity = not (self.prox_bit and p[3] & self.prox_bit)
        return TabletEvent(x, y, proximity, buttons, None, None, None, self.tool, timestamp)


class CalcompEncoder(TabletEncoder):
    name = NAME

    def __init__(self, model: TabletModel = DEFAULT_MODEL, *, prox_bit: int = 0x20) -> None:
        super().__init__(model)
        self.prox_bit = prox_bit
        self.streaming = True

    def encode(self, event: TabletEvent) -> bytes:
        x, y = self.checked_xy(event)
        buttons = clamp_check(event.buttons, 0, 15, "buttons")
        if not event.proximity and not self.prox_bit:
            raise ProtocolError("this CalComp variant has no proximity bit")
        b3 = y >> 14 | (0 if event.proximity else self.prox_bit)
        return bytes((0x80 | buttons << 2 | x >> 14, x >> 7 & 0x7F, x & 0x7F,
                      b3, y >> 7 & 0x7F, y & 0x7F))

    def split_commands(self, data: bytes) -> tuple[list[bytes], bytes]:
        # Commands are ESC % ... CR; a lone "?" prompts one report.
        commands: list[bytes] = []
        rest = data
        while rest:
            if rest[:1] == b"?":
                commands.append(b"?")
                rest = rest[1:]
                continue
            start = rest.find(b"\x1b%")
            if start < 0:
                return commands, b""
            end = rest.find(b"\r", start)
            if end < 0:
                return commands, rest[start:]
            commands.append(rest[start + 2 : end])
            rest = rest[end + 1 :]
        return commands, b""

    def answer(self, command: bytes) -> bytes:
        if command == b"VS":  # send configuration: a frame holding max X / max Y
            return self.encode(TabletEvent(self.model.max_x, self.model.max_y))
        if command in (b"__V", b"__p"):
            return FIRMWARE_ID
        if command == b"H":
            self.streaming = False
        elif command == b"IR":
            self.streaming = True
        return b""
