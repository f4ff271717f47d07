"""Loader for the character generator ROM text file (chargen.txt)."""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent


class RomError(ValueError):
    """A ROM text file is malformed; the message names the file and line."""


@dataclass(frozen=True)
class Font:
    width: int
    height: int
    baseline: int  # rows of the glyph that stand on the baseline (the rest descend)
    glyphs: np.ndarray  # (256, height, width) bool, row 0 = top of the glyph

    def glyph(self, code: int) -> np.ndarray:
        return self.glyphs[code & 0xFF]


def _fail(path: Path, lineno: int, why: str) -> RomError:
    return RomError(f"{path}:{lineno}: {why}")


def parse_font(text: str, path: Path) -> Font:
    header: dict[str, int] = {}
    glyph_rows: dict[int, list[str]] = {}
    current: int | None = None
    for lineno, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if not line or line.startswith("# ") or line == "#":
            continue  # comments are "# ..." (a glyph row never holds a space)
        word = line.split()
        if word[0] in ("width", "height", "baseline") and current is None:
            if len(word) != 2 or not word[1].isdigit():
                raise _fail(path, lineno, f"expected '{word[0]} <number>'")
            header[word[0]] = int(word[1])
        elif word[0] == "char":
            try:
                current = int(word[1], 16)
            except (IndexError, ValueError):
                raise _fail(path, lineno, "expected 'char <hex code> <name>'") from None
            if not 0 <= current <= 255 or current in glyph_rows:
                raise _fail(path, lineno, f"bad or repeated character code {word[1]}")
            glyph_rows[current] = []
        else:
            if current is None:
                raise _fail(path, lineno, "glyph row before any 'char' line")
            if set(line) - {"#", "."}:
                raise _fail(path, lineno, "glyph rows use only '#' and '.'")
            glyph_rows[current].append(line)
    for key in ("width", "height", "baseline"):
        if key not in header:
            raise RomError(f"{path}: missing '{key}' line")
    w, h = header["width"], header["height"]
    glyphs = np.zeros((256, h, w), dtype=bool)
    for code, rows in glyph_rows.items():
        if len(rows) > h or any(len(r) != w for r in rows):
            raise RomError(f"{path}: glyph {code:02X} is not {w} wide and at most {h} high")
        for r, row in enumerate(rows):
            glyphs[code, r] = [c == "#" for c in row]
    return Font(w, h, header["baseline"], glyphs)


@lru_cache(maxsize=4)
def load_font(path: Path | None = None) -> Font:
    p = Path(path) if path is not None else HERE / "chargen.txt"
    return parse_font(p.read_text(encoding="ascii"), p)
