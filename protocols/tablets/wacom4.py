"""Wacom protocol IV (serial UD/ArtZ, PenPartner, serial Graphire, PL/Cintiq).

Packet layout, pressure bit packing and model table follow the Linux driver
``drivers/input/tablet/wacom_serial4.c`` (facts §1); tilt packets (9 bytes) follow TabletMagic
and linuxwacom because the kernel does not implement them.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

from camlab88.protocols.tablets.base import (
    ProtocolError,
    TabletEncoder,
    TabletParser,
    clamp_check,
    one_of,
)
from camlab88.protocols.tablets.events import DeviceReply, TabletEvent, TabletModel

NAME = "wacom4"
# A 12x12 inch tablet at 1270 lpi: TabletMagic's default and the ~C the emulator answers.
DEFAULT_MODEL = TabletModel("Wacom UD (protocol IV)", 15240, 15240, 1270.0, 255, None)
REPLY_LIMIT = 128  # longest ~ reply kept; longer means noise, not a reply


@dataclass(frozen=True)
class WacomIdentity:
    """What ``~#`` says: two-letter model code and ROM version."""

    code: str
    version: tuple[int, int]
    text: str

    @property
    def extra_z_bits(self) -> int:
        if self.code == "ET":
            return 2
        if self.code == "PL" and re.search(r"PL-?(550|800|710)", self.text):
            return 2
        if self.code == "UD" and self.version <= (1, 2):
            return 0
        return 1

    @property
    def eraser_mask(self) -> int:
        return 0x08 if self.code == "ET" else 0x04

    @property
    def lines_per_inch(self) -> float | None:
        """Fixed resolutions the kernel knows; None = ask with ``~R``."""
        if self.code == "CT":
            return 1000.0
        if self.code == "ET":
            return 1016.0
        if self.code in ("PL", "DT"):
            return 2540.0 if "710" in self.text else 508.0
        return None

    @property
    def fixed_max(self) -> tuple[int, int] | None:
        return (5103, 3711) if self.code == "ET" else None

    @property
    def setup_string(self) -> bytes:
        """What the kernel sends after identification (facts §1.3)."""
        if self.code == "CT":
            return b"PH1\rST\r"
        if self.code in ("PL", "DT"):
            return b"OC1\rIT0\rSR\rST\r"
        return b"MU1\rOC1\r~M0\r~M1\rIT0\rIN0\rSR\rZF1\rST\r"


def parse_model_reply(text: str) -> WacomIdentity:
    """``~#CT-0045R00,V1.3-5,`` -> code CT, version (1, 3); version follows the LAST ``V``."""
    if not text.startswith("~#") or len(text) < 4:
        raise ProtocolError(f"not a ~# model reply: {text!r}")
    code = text[2:4]
    at = text.rfind("V")
    match = re.match(r"V(\d+)\.(\d+)", text[at:]) if at >= 0 else None
    if match is None:
        raise ProtocolError(f"no ROM version in model reply {text!r}")
    return WacomIdentity(code, (int(match.group(1)), int(match.group(2))), text)


def parse_coords_reply(text: str) -> tuple[int, int]:
    """``~C15240,15240`` -> (max_x, max_y)."""
    match = re.fullmatch(r"~C(\d+),(\d+)\s*", text)
    if match is None:
        raise ProtocolError(f"not a ~C coordinate reply: {text!r}")
    return int(match.group(1)), int(match.group(2))


@dataclass(frozen=True)
class WacomSettings:
    """The ``~R`` reply: 32-bit settings word plus increment, interval and resolution."""

    word: int
    increment: int
    interval: int
    res_x: int
    res_y: int

    @property
    def command_set(self) -> str:
        return ("bitpad2", "mm1201", "wacom2s", "wacom4")[self.word >> 30 & 3]

    @property
    def baud(self) -> int:
        return 2400 << (self.word >> 28 & 3)

    @property
    def parity(self) -> str:
        return ("N", "N", "O", "E")[self.word >> 26 & 3]

    @property
    def data_bits(self) -> int:
        return 8 if self.word >> 25 & 1 else 7

    @property
    def stop_bits(self) -> int:
        return 2 if self.word >> 24 & 1 else 1

    @property
    def tilt(self) -> bool:
        return bool(self.word >> 4 & 1)

    @property
    def packet_length(self) -> int:
        return 9 if self.command_set == "wacom4" and self.tilt else 7

    def reply_text(self) -> str:
        return (
            f"~R{self.word:08X},{self.increment:03d},{self.interval:02d},"
            f"{self.res_x:04d},{self.res_y:04d}"
        )


def parse_settings_reply(text: str) -> WacomSettings:
    """``~RE202C900,002,02,1270,1270`` (kernel format ``~R%x,%u,%u,%u,%u``)."""
    match = re.fullmatch(r"~R([0-9A-Fa-f]{1,8}),(\d+),(\d+),(\d+),(\d+)\s*", text)
    if match is None:
        raise ProtocolError(f"not a ~R settings reply: {text!r}")
    word, *rest = match.groups()
    return WacomSettings(int(word, 16), *(int(v) for v in rest))


def settings_word(tilt: bool = False, baud: int = 9600, lpi: int = 1270) -> int:
    """Settings word of a Wacom IV tablet: 8N1, stream, binary, absolute, max rate."""
    res_code = {500: 0, 508: 1, 1000: 2, 1270: 3}.get(lpi, 3)
    baud_code = {2400: 0, 4800: 1, 9600: 2, 19200: 3}[baud]
    return (
        3 << 30 | baud_code << 28 | 1 << 25 | 1 << 23 | 3 << 20 | 3 << 16 | res_code << 14
        | (1 << 4 if tilt else 0)
    )


def _signed7(byte: int) -> int:
    return (byte & 0x3F) - (byte & 0x40)


class Wacom4Parser(TabletParser):
    """Binary packets plus the ``~`` ASCII replies interleaved with them."""

    name = NAME
    checks_range = True

    def __init__(
        self,
        model: TabletModel = DEFAULT_MODEL,
        *,
        tilt: bool = False,
        extra_z_bits: int = 1,
        eraser_mask: int = 0x04,
        parmrk: bool = False,
    ) -> None:
        super().__init__(model, parmrk)
        self.extra_z_bits = one_of("extra_z_bits", extra_z_bits, (0, 1, 2))
        self.eraser_mask = eraser_mask
        self._use_framer(9 if tilt else 7)
        self._reply: bytearray | None = None

    @property
    def tilt(self) -> bool:
        return self._framer.length == 9

    def set_tilt(self, tilt: bool) -> None:
        """9-byte packets (after ``FM1``, or when ``~R`` reports tilt) or 7-byte ones."""
        self._framer.reset()
        self._framer.length = 9 if tilt else 7

    def identify(self, identity: WacomIdentity) -> None:
        """Adopt what ``~#`` told us (pressure bits, eraser mask, fixed resolution/size)."""
        self.extra_z_bits = identity.extra_z_bits
        self.eraser_mask = identity.eraser_mask
        lpi = identity.lines_per_inch or self.model.lines_per_inch
        max_x, max_y = identity.fixed_max or (self.model.max_x, self.model.max_y)
        self.model = replace(
            self.model, name=f"Wacom {identity.code}", lines_per_inch=lpi, max_x=max_x,
            max_y=max_y, pressure_max=(1 << (7 + self.extra_z_bits)) - 1,
        )

    def flush(self, timestamp: float = 0.0) -> list[TabletEvent]:
        # A PenPartner ends its replies without CR: the kernel waits 1 s, then takes them.
        self._end_reply(timestamp)
        return []

    def _end_reply(self, timestamp: float) -> None:
        if self._reply:
            self._replies.append(DeviceReply(self._reply.decode("ascii", "replace"), timestamp))
            self.stats.replies += 1
        self._reply = None

    def _byte(self, byte: int, ok: bool, timestamp: float) -> TabletEvent | None:
        if not ok:
            self._framer.reset()
            self._reply = None
            return None
        if self._reply is not None:
            if byte == 0x0D:
                self._end_reply(timestamp)
                return None
            if not byte & 0x80:
                self._reply.append(byte)
                if len(self._reply) > REPLY_LIMIT:
                    self.stats.dropped_bytes += len(self._reply)
                    self._reply = None
                return None
            self._end_reply(timestamp)  # a packet started: the reply had no CR
        elif byte == 0x7E and self._framer.pending == 0:
            self._reply = bytearray(b"~")
            return None
        packet = self._framer.push(byte)
        return None if packet is None else self.decode(packet, timestamp)

    def decode(self, p: bytes, timestamp: float = 0.0) -> TabletEvent:
        proximity = bool(p[0] & 0x40)
        stylus = bool(p[0] & 0x20)
        x = (p[0] & 3) << 14 | p[1] << 7 | p[2]
        y = (p[3] & 3) << 14 | p[4] << 7 | p[5]
        buttons = (p[3] & 0x78) >> 3
        pressure = None
        if stylus:
            tool = "eraser" if buttons & self.eraser_mask else "pen"
            if proximity:
                z = p[6] & 0x7F
                if self.extra_z_bits >= 1:
                    z = z << 1 | (p[3] & 4) >> 2
                if self.extra_z_bits > 1:
                    z = z << 1 | (p[0] & 4) >> 2
                pressure = z ^ (0x40 << self.extra_z_bits)
        else:
            tool = "puck"
        tilt_x = tilt_y = None
        if len(p) == 9:
            tilt_x, tilt_y = _signed7(p[7]), _signed7(p[8])
        return TabletEvent(x, y, proximity, buttons, pressure, tilt_x, tilt_y, tool, timestamp)


class Wacom4Encoder(TabletEncoder):
    """Builds protocol IV packets and answers the ASCII queries like a UD tablet."""

    name = NAME

    def __init__(
        self,
        model: TabletModel = DEFAULT_MODEL,
        *,
        tilt: bool = False,
        extra_z_bits: int = 1,
        eraser_mask: int = 0x04,
        identity: str = "~#UD-1212-R00 V1.4-4",
    ) -> None:
        super().__init__(model)
        self.tilt = tilt
        self.extra_z_bits = extra_z_bits
        self.eraser_mask = eraser_mask
        self.identity = identity
        self.streaming = True

    def encode(self, event: TabletEvent) -> bytes:
        x, y = self.checked_xy(event)
        buttons = clamp_check(event.buttons, 0, 15, "buttons")
        stylus = event.tool in ("pen", "eraser")
        if event.tool == "eraser":
            buttons |= self.eraser_mask
        elif stylus and buttons & self.eraser_mask:
            raise ProtocolError(f"pen buttons {buttons:#x} would read back as the eraser")
        b0 = 0x80 | (0x40 if event.proximity else 0) | (0x20 if stylus else 0)
        b0 |= 0x08 if buttons else 0
        b0 |= x >> 14
        b3 = buttons << 3 | y >> 14
        b6 = 0
        if stylus and event.proximity:
            top = (1 << (7 + self.extra_z_bits)) - 1
            z = clamp_check(event.pressure or 0, 0, top, "pressure")
            raw = z ^ (0x40 << self.extra_z_bits)
            if self.extra_z_bits > 1:
                b0 |= (raw & 1) << 2
                raw >>= 1
            if self.extra_z_bits >= 1:
                b3 |= (raw & 1) << 2
                raw >>= 1
            b6 = raw & 0x7F
        packet = bytes((b0, x >> 7 & 0x7F, x & 0x7F, b3, y >> 7 & 0x7F, y & 0x7F, b6))
        if self.tilt:
            tx = clamp_check(event.tilt_x or 0, -64, 63, "tilt X")
            ty = clamp_check(event.tilt_y or 0, -64, 63, "tilt Y")
            packet += bytes((tx & 0x7F, ty & 0x7F))
        return packet

    def split_commands(self, data: bytes) -> tuple[list[bytes], bytes]:
        commands: list[bytes] = []
        buf = bytearray()
        for b in data:
            if b == 0x0D:
                if buf:
                    commands.append(bytes(buf))
                buf.clear()
                continue
            if not buf and b in (0x23, 0x24):  # "\r#" / "\r$" resets need no CR of their own
                commands.append(bytes((b,)))
                continue
            buf.append(b)
            if bytes(buf) == b"~#":  # the kernel sends ~# without CR
                commands.append(b"~#")
                buf.clear()
        return commands, bytes(buf)

    def answer(self, command: bytes) -> bytes:
        if command == b"~#":
            return self.identity.encode("ascii") + b"\r"
        if command == b"~C":
            return f"~C{self.model.max_x},{self.model.max_y}\r".encode()
        if command in (b"~R", b"~R1", b"~R2"):
            lpi = int(self.model.lines_per_inch)
            word = settings_word(tilt=self.tilt, lpi=lpi)
            text = WacomSettings(word, 0, 0, lpi, lpi).reply_text()
            return text.encode("ascii") + b"\r"
        if command == b"SP":
            self.streaming = False
        elif command == b"ST":
            self.streaming = True
        elif command == b"FM1":
            self.tilt = True
        elif command == b"FM0":
            self.tilt = False
        return b""
