"""Colour strings in scene files and the command line."""

from __future__ import annotations


def parse_hex(c: object) -> tuple[int, int, int]:
    if not isinstance(c, str) or len(c) != 7 or c[0] != "#":
        raise ValueError(f"colour {c!r} is not \"#rrggbb\"")
    try:
        return int(c[1:3], 16), int(c[3:5], 16), int(c[5:7], 16)
    except ValueError:
        raise ValueError(f"colour {c!r} is not \"#rrggbb\"") from None
