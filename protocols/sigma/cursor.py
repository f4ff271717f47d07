"""The cursor report the terminal sends up the line after HF.

Format (product decision, facts/sigma.md 7 and "Product decisions"): one key byte, X as
3 digits (4 after IO), a comma, Y likewise, then CR — plain device coordinates, no excess-100.
That is 9 bytes (11 after IO): PGPLOT reads 9 characters, RAL GKS reads 8 (10) and stops
before the CR.
"""

from __future__ import annotations

from dataclasses import dataclass

CURSOR_BREAK = 0x1A  # CTRL-Z: RAL GKS takes it as "break" (no input)


@dataclass(frozen=True, slots=True)
class CursorReport:
    key: int
    x: int
    y: int


def format_report(key: int, x: int, y: int, digits: int = 3) -> bytes:
    top = 10**digits - 1
    x = min(max(int(x), 0), top)
    y = min(max(int(y), 0), top)
    return bytes((key & 0xFF,)) + f"{x:0{digits}d},{y:0{digits}d}\r".encode("ascii")


def parse_report(data: bytes, digits: int = 3) -> CursorReport:
    """Parse one report (the trailing CR is optional); ValueError names the bad byte offset."""
    need = 2 + 2 * digits
    if len(data) < need:
        raise ValueError(f"cursor report too short: {len(data)} bytes, need {need}")
    for off in list(range(1, 1 + digits)) + list(range(2 + digits, need)):
        if not 0x30 <= data[off] <= 0x39:
            raise ValueError(f"cursor report byte {off} is {data[off]:#04x}, not a digit")
    if data[1 + digits] != 0x2C:
        raise ValueError(f"cursor report byte {1 + digits} is not the ',' separator")
    x = int(data[1:1 + digits])
    y = int(data[2 + digits:need])
    return CursorReport(data[0], x, y)
