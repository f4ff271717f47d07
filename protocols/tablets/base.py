"""What every serial tablet protocol module provides: a parser and an encoder."""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Callable
from typing import TypeVar

from camlab88.protocols.tablets.events import DeviceReply, TabletEvent, TabletModel
from camlab88.protocols.tablets.framing import ParmrkFilter, ParseStats, SyncFramer

T = TypeVar("T")


class ProtocolError(ValueError):
    """An option or value the protocol cannot represent."""


class TabletParser(ABC):
    """Incremental decoder: feed bytes split anywhere, get whole events back.

    ``parmrk=True`` means the byte stream carries POSIX PARMRK marks (the serial source turns
    them on when the line has parity): a byte flagged as a parity error spoils its packet.
    """

    name: str = ""
    # Binary formats: a cut packet completed by line noise still frames correctly, so a
    # coordinate beyond the model's maximum marks the packet bad (ASCII lines check
    # themselves digit by digit).  Off while a size reply is awaited (it may be larger).
    checks_range: bool = False

    def __init__(self, model: TabletModel, parmrk: bool = False) -> None:
        self.model = model
        self.range_check = self.checks_range
        self.stats = ParseStats()
        self._parmrk = ParmrkFilter() if parmrk else None
        self._replies: list[DeviceReply] = []

    def feed(self, data: bytes, timestamp: float = 0.0) -> list[TabletEvent]:
        out: list[TabletEvent] = []
        if self._parmrk is not None:
            pairs = self._parmrk.feed(data)
        else:
            pairs = [(b, True) for b in data]
        for byte, ok in pairs:
            if not ok:
                self.stats.parity_errors += 1
            event = self._byte(byte, ok, timestamp)
            if event is None:
                continue
            if self.range_check and not (0 <= event.x <= self.model.max_x
                                         and 0 <= event.y <= self.model.max_y):
                self.stats.bad_packets += 1
                continue
            out.append(event)
        return out

    def _use_framer(self, packet_size: int) -> None:
        """Binary packets of ``packet_size`` bytes framed on the sync bit (framing.py)."""
        self._framer = SyncFramer(packet_size)
        self.stats = self._framer.stats

    def take_replies(self) -> list[DeviceReply]:
        replies, self._replies = self._replies, []
        return replies

    def flush(self, timestamp: float = 0.0) -> list[TabletEvent]:
        """End of input (or a reply timeout): finish anything that can be finished."""
        return []

    @abstractmethod
    def _byte(self, byte: int, ok: bool, timestamp: float) -> TabletEvent | None: ...


class SyncFramedParser(TabletParser):
    """A binary format whose packets start at a byte with the sync bit set (Calcomp,
    Summagraphics): the framing is shared, ``decode`` turns one whole packet into an event
    (or None for a packet that is not a report)."""

    def _byte(self, byte: int, ok: bool, timestamp: float) -> TabletEvent | None:
        if not ok:  # a parity error spoils the packet it falls in
            self._framer.reset()
            return None
        packet = self._framer.push(byte)
        return None if packet is None else self.decode(packet, timestamp)

    @abstractmethod
    def decode(self, p: bytes, timestamp: float = 0.0) -> TabletEvent | None: ...


class TabletEncoder(ABC):
    """Turns events into the bytes the real tablet would send (for the emulated tablet)."""

    name: str = ""
    xy_max: int = 0xFFFF  # the largest X or Y the format's fields hold

    def __init__(self, model: TabletModel) -> None:
        self.model = model

    def checked_xy(self, event: TabletEvent) -> tuple[int, int]:
        """The event's X and Y, or ProtocolError for one the format cannot hold."""
        return (clamp_check(event.x, 0, self.xy_max, "X"),
                clamp_check(event.y, 0, self.xy_max, "Y"))

    @abstractmethod
    def encode(self, event: TabletEvent) -> bytes: ...

    def startup(self) -> bytes:
        """Bytes the tablet sends by itself at power-on (most send nothing)."""
        return b""

    def answer(self, command: bytes) -> bytes:
        """Reply to one complete host command (default: tablets that never answer)."""
        return b""

    def split_commands(self, data: bytes) -> tuple[list[bytes], bytes]:
        """Split host bytes into complete commands; return (commands, unfinished rest)."""
        return [], b""


def one_of(what: str, value: T, allowed: tuple[T, ...],
           show: Callable[[T], str] = repr) -> T:
    """``value`` if it is one of ``allowed``, else ProtocolError naming the choices."""
    if value not in allowed:
        choices = ", ".join(map(show, allowed[:-1])) + f" or {show(allowed[-1])}"
        raise ProtocolError(f"{what} must be {choices}, not {show(value)}")
    return value


def clamp_check(value: int, low: int, high: int, what: str) -> int:
    if not low <= value <= high:
        raise ProtocolError(f"{what} {value} outside {low}..{high}")
    return value
