"""Framing for the ASCII tablet formats: one report per terminated line.

There is no sync bit, so the line terminator is the resync point: a damaged line is dropped
whole and the next line decodes normally.  These tablets send 7-bit characters; when the
line has parity and is read as 8N1 (the same 10-bit frame as 7E1/7O1 -- and all a pty or a
socket can carry) bit 7 is the parity bit, checked here.
"""

from __future__ import annotations

import re
from abc import abstractmethod
from collections.abc import Callable
from typing import ClassVar

from camlab88.protocols.tablets.base import TabletParser, one_of
from camlab88.protocols.tablets.events import TabletEvent, TabletModel
from camlab88.protocols.tablets.framing import add_parity, parity_ok

LINE_LIMIT = 64  # no report or reply is this long; longer means noise without a terminator


class AsciiLineParser(TabletParser):
    def __init__(
        self,
        model: TabletModel,
        decode_line: Callable[[str, float], TabletEvent | None],
        *,
        parity: str = "N",
        terminators: bytes = b"\r\n",
        parmrk: bool = False,
    ) -> None:
        super().__init__(model, parmrk)
        self.parity = one_of("parity", parity, ("N", "E", "O"))
        self._decode_line = decode_line
        self._terminators = terminators
        self._line = bytearray()
        self._spoilt = False

    def _byte(self, byte: int, ok: bool, timestamp: float) -> TabletEvent | None:
        if not ok or not parity_ok(byte, self.parity):
            if ok:
                self.stats.parity_errors += 1
            self._spoilt = True
        char = byte & 0x7F if self.parity != "N" else byte
        if char in self._terminators:
            line, spoilt = bytes(self._line), self._spoilt
            self._line.clear()
            self._spoilt = False
            if not line and not spoilt:
                return None  # the LF of a CR LF pair
            if spoilt:
                self.stats.bad_packets += 1
                return None
            return self._finish(line, timestamp)
        self._line.append(char)
        if len(self._line) > LINE_LIMIT:
            self.stats.dropped_bytes += len(self._line)
            self._line.clear()
            self._spoilt = True  # the tail up to the next terminator is junk too
        return None

    def _finish(self, line: bytes, timestamp: float) -> TabletEvent | None:
        try:
            text = line.decode("ascii")
            event = self._decode_line(text, timestamp)
        except (UnicodeDecodeError, ValueError):
            self.stats.bad_packets += 1
            return None
        if event is not None:
            self.stats.packets += 1
        return event


def apply_parity(data: bytes, parity: str) -> bytes:
    return bytes(add_parity(b, parity) for b in data)


def bit_pad_model(name: str) -> TabletModel:
    """A Bit Pad's active area as the factory sets it: 2200 x 2200 at 200 lpi (11 inches
    square), origin lower-left; One and Two alike."""
    return TabletModel(name, 2200, 2200, 200.0, None, None, origin="lower-left")


class AsciiReportParser(AsciiLineParser):
    """A tablet whose every report is one ASCII line ``XXXX,YYYY,F`` (the Bit Pads): four
    decimal digits of X and of Y and a flag character.  A subclass names its default model,
    parity and line terminators, the flag characters it sends (``flags``, a regex class) and
    ``flag_state(flag) -> (proximity, buttons)``."""

    default_model: ClassVar[TabletModel]
    default_parity: ClassVar[str]
    terminators: ClassVar[bytes]
    flags: ClassVar[str]

    def __init__(self, model: TabletModel | None = None, *, parity: str | None = None,
                 tool: str = "puck", parmrk: bool = False) -> None:
        super().__init__(model if model is not None else self.default_model,
                         self._line_decoder(tool),
                         parity=self.default_parity if parity is None else parity,
                         terminators=self.terminators, parmrk=parmrk)

    @staticmethod
    @abstractmethod
    def flag_state(flag: str) -> tuple[bool, int]: ...

    def _line_decoder(self, tool: str) -> Callable[[str, float], TabletEvent]:
        line = re.compile(rf"(\d{{4}}),(\d{{4}}),([{self.flags}])")

        def decode(text: str, timestamp: float) -> TabletEvent:
            match = line.fullmatch(text)
            if match is None:
                raise ValueError(f"not a {self.default_model.name} report: {text!r}")
            proximity, buttons = self.flag_state(match.group(3))
            return TabletEvent(int(match.group(1)), int(match.group(2)), proximity, buttons,
                               None, None, None, tool, timestamp)

        return decode
