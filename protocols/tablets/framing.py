"""Incremental framing shared by the serial parsers.

Binary tablet protocols mark the first byte of a packet with bit 7 set and every other byte
with bit 7 clear; a receiver that joins mid-stream (or loses a byte to line noise) drops bytes
until the next sync byte.  ASCII protocols frame on the line terminator instead.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass
class ParseStats:
    packets: int = 0
    dropped_bytes: int = 0  # bytes thrown away while hunting for a sync byte
    bad_packets: int = 0  # well-framed packets whose content was invalid
    parity_errors: int = 0
    replies: int = 0


class SyncFramer:
    """Collects fixed-length packets whose first byte has ``sync_mask`` bits == ``sync_value``.

    A byte with the sync pattern always restarts a packet (the kernel's rule for Wacom IV);
    a continuation byte with bit 7 set is therefore a restart, never data.
    """

    def __init__(self, length: int, sync_mask: int = 0x80, sync_value: int = 0x80) -> None:
        self.length = length
        self.sync_mask = sync_mask
        self.sync_value = sync_value
        self._buf = bytearray()
        self.stats = ParseStats()

    def reset(self) -> None:
        self.stats.dropped_bytes += len(self._buf)
        self._buf.clear()

    @property
    def pending(self) -> int:
        return len(self._buf)

    def push(self, byte: int) -> bytes | None:
        """Add one byte; return a complete packet when one is finished."""
        if byte & self.sync_mask == self.sync_value:
            if self._buf:
                self.stats.dropped_bytes += len(self._buf)  # truncated packet
            self._buf = bytearray((byte,))
        elif not self._buf or byte & 0x80:
            self.stats.dropped_bytes += 1
            return None
        else:
            self._buf.append(byte)
        if len(self._buf) == self.length:
            packet = bytes(self._buf)
            self._buf.clear()
            self.stats.packets += 1
            return packet
        return None


class ParmrkFilter:
    """Undo the POSIX ``PARMRK`` marking a serial driver applies when parity checking is on.

    With ``INPCK|PARMRK`` a byte received with a parity or framing error arrives as
    ``FF 00 <byte>`` and a real ``FF`` as ``FF FF``.  A pty or socket carries no parity bit,
    so this is how a wrong-parity byte reaches a program through the OS; the filter yields
    ``(byte, ok)`` pairs.
    """

    def __init__(self) -> None:
        self._state = 0  # 0 normal, 1 after FF, 2 after FF 00

    def feed(self, data: bytes) -> list[tuple[int, bool]]:
        out: list[tuple[int, bool]] = []
        for b in data:
            if self._state == 0:
                if b == 0xFF:
                    self._state = 1
                else:
                    out.append((b, True))
            elif self._state == 1:
                if b == 0xFF:
                    out.append((0xFF, True))
                    self._state = 0
                elif b == 0x00:
                    self._state = 2
                else:  # not a mark after all: keep both bytes
                    out.append((0xFF, True))
                    out.append((b, True))
                    self._state = 0
            else:
                out.append((b, False))
                self._state = 0
        return out


def parity_ok(byte: int, parity: str) -> bool:
    """Check a 7-data-bit character whose bit 7 carries the parity bit (7E1/7O1 read as 8N1)."""
    ones = bin(byte & 0xFF).count("1")
    if parity == "E":
        return ones % 2 == 0
    if parity == "O":
        return ones % 2 == 1
    return True


def add_parity(byte: int, parity: str) -> int:
    """Set bit 7 of a 7-bit character so the 8 bits have the requested parity."""
    byte &= 0x7F
    ones = bin(byte).count("1")
    if parity == "E":
        return byte | (0x80 if ones % 2 else 0)
    if parity == "O":
        return byte | (0 if ones % 2 else 0x80)
    return byte
