"""Loader for the power-on lookup tables (t5684.lut, t5688.lut)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from camlab88.roms.sigma.chargen import RomError

HERE = Path(__file__).resolve().parent


def parse_lut(text: str, path: Path, entries: int) -> np.ndarray:
    """(entries, 3) uint8 RGB, each gun scaled to 8 bits."""
    guns = 0
    lut = np.zeros((entries, 3), dtype=np.uint8)
    seen = set()
    for lineno, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        word = line.split()
        if word[0] == "guns":
            if len(word) != 2 or word[1] not in ("4", "8"):
                raise RomError(f"{path}:{lineno}: expected 'guns 4' or 'guns 8'")
            guns = int(word[1])
            continue
        if not guns:
            raise RomError(f"{path}:{lineno}: entry before the 'guns' line")
        try:
            i, r, g, b = (int(v, 16) for v in word)
        except ValueError:
            raise RomError(f"{path}:{lineno}: expected 'index red green blue' in hex") from None
        top = (1 << guns) - 1
        if not 0 <= i < entries or i in seen or max(r, g, b) > top or min(r, g, b) < 0:
            raise RomError(f"{path}:{lineno}: entry out of range or repeated")
        seen.add(i)
        scale = 17 if guns == 4 else 1
        lut[i] = (r * scale, g * scale, b * scale)
    if len(seen) != entries:
        raise RomError(f"{path}: {len(seen)} entries, expected {entries}")
    return lut


_LOADED: dict[str, np.ndarray] = {}


def load_lut(model: str) -> np.ndarray:
    """The model's power-on LUT, parsed once per process (a T5688's takes ~1 ms to parse,
    paid at every power-on and HH otherwise). A fresh copy each call: callers change it."""
    if model not in _LOADED:
        entries = {"t5684": 16, "t5688": 256}[model]
        p = HERE / f"{model}.lut"
        _LOADED[model] = parse_lut(p.read_text(encoding="ascii"), p, entries)
    return _LOADED[model].copy()
