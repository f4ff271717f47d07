"""Abbreviated graphics mode (AGS): Tektronix-style point bytes, both directions.

Facts (facts/sigma.md 4.2, RAL GKS gk0sln): a point is HiY, [EB], LoY, HiX, LoX with
HiY = 32 + (y mod 1024) div 32, LoY = 96 + y mod 32, HiX = 32 + (x mod 1024) div 32,
LoX = 64 + x mod 32 and, on high-resolution models only, EB = 96 + 4 (y div 1024) + x div 1024.
The encoder omits bytes by the gk0sln rules; the decoder uses the Tektronix rules
(a high byte after a low-Y byte is HiX, a low byte followed by another low byte is EB) and
is vectorised with numpy because AGS is the bulk of a vector-heavy stream.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np


def point_bytes(x: int, y: int) -> tuple[int, int, int, int, int]:
    """(HiY, EB, LoY, HiX, LoX) of one point."""
    return (32 + (y % 1024) // 32, 96 + 4 * (y // 1024) + x // 1024, 96 + y % 32,
            32 + (x % 1024) // 32, 64 + x % 32)


class AgsPointEncoder:
    """Encodes successive points of one JH ... US run with gk0sln's omission rules."""

    def __init__(self, high_res: bool = False) -> None:
        self.high_res = high_res
        self.limit = 2047 if high_res else 1023
        self._last = (-1, -1, -1, -1)  # HiY, EB, LoY, HiX last sent

    def encode(self, x: int, y: int) -> bytes:
        x, y = int(x), int(y)
        if not (0 <= x <= self.limit and 0 <= y <= self.limit):
            raise ValueError(f"AGS point ({x}, {y}) outside 0..{self.limit}")
        hiy, eb, loy, hix, lox = point_bytes(x, y)
        last_hiy, last_eb, last_loy, last_hix = self._last
        out = bytearray()
        if hiy != last_hiy:
            out.append(hiy)
        if self.high_res and eb != last_eb:
            out += bytes((eb, loy))
            if hix != last_hix:
                out.append(hix)
        elif hix != last_hix:
            out += bytes((loy, hix))
        elif loy != last_loy:
            out.append(loy)
        out.append(lox)
        self._last = (hiy, eb if self.high_res else last_eb, loy, hix)
        return bytes(out)


def encode_points(points: Iterable[tuple[int, int]], high_res: bool = False) -> bytes:
    enc = AgsPointEncoder(high_res)
    return b"".join(enc.encode(x, y) for x, y in points)


# decoder state registers (int32 array) used by scan_points
HIY, EB, LOY, HIX, LAST_LO, PENDING = range(6)


def new_state() -> np.ndarray:
    """Decoder registers HiY, EB, LoY, HiX, last-byte-was-low, bytes since the last point."""
    return np.zeros(6, dtype=np.int32)


def scan_points(buf: np.ndarray | bytes, start: int, state: np.ndarray, out: np.ndarray,
                k: int) -> tuple[int, int]:
    """Decode AGS point bytes of ``buf`` from ``start`` until US, ESC or the end.

    Plain Python over numpy arrays so that the emulator can compile this very function with
    numba (emulator.sigma.fast) while the protocol package stays numba-free: one definition
    of the decoding, two speeds. Tektronix rules, byte by byte: a low byte (0x60-0x7F) right
    after another low byte makes the earlier one EB; a high byte (0x20-0x3F) after a low
    byte is HiX, otherwise HiY; LoX (0x40-0x5F) completes a point, written to ``out[k]``.
    Other control bytes (CR, LF, NUL...) are ignored. Returns (index reached, new k).
    ``out`` must have room for one point per remaining byte.
    """
    hiy = int(state[0])
    eb = int(state[1])
    loy = int(state[2])
    hix = int(state[3])
    last_lo = int(state[4])
    pending = int(state[5])
    i = start
    n = len(buf)
    while i < n:
        b = int(buf[i])
        if b == 0x1F or b == 0x1B:
            break
        i += 1
        if b < 0x20 or b > 0x7F:
            continue
        c = b >> 5
        v = b & 31
        if c == 3:
            if last_lo:
                eb = loy
            loy = v
            last_lo = 1
            pending += 1
        elif c == 1:
            if last_lo:
                hix = v
            else:
                hiy = v
            last_lo = 0
            pending += 1
        else:
            out[k, 0] = hix * 32 + v + 1024 * (eb & 3)
            out[k, 1] = hiy * 32 + loy + 1024 * ((eb >> 2) & 3)
            k += 1
            last_lo = 0
            pending = 0
    state[0] = hiy
    state[1] = eb
    state[2] = loy
    state[3] = hix
    state[4] = last_lo
    state[5] = pending
    return i, k
