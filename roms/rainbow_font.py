"""Loader for the Rainbow's text font (roms/rainbow_font.txt; lines starting ";" are comments)."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import numpy as np

FONT_PATH = Path(__file__).with_name("rainbow_font.txt")


class FontError(ValueError):
    pass


@lru_cache(maxsize=4)
def load_font(path: Path = FONT_PATH) -> tuple[int, int, dict[int, np.ndarray]]:
    """(cell width, cell height, {character code: bool array (h, w)})."""
    glyphs: dict[int, np.ndarray] = {}
    cw = ch = 0
    code: int | None = None
    rows: list[str] = []
    text = path.read_text(encoding="ascii").splitlines()

    def close(lineno: int) -> None:
        if code is None:
            return
        if len(rows) != ch:
            raise FontError(f"{path}:{lineno}: glyph {code} has {len(rows)} rows, want {ch}")
        glyphs[code] = np.array([[c == "#" for c in r] for r in rows], dtype=bool)

    for n, line in enumerate(text, 1):
        if not line or line.startswith(";"):
            continue
        if line.startswith("cell "):
            try:
                cw, ch = (int(v) for v in line.split()[1:3])
            except ValueError:
                raise FontError(f"{path}:{n}: bad cell line {line!r}") from None
        elif line.startswith("char "):
            close(n)
            try:
                code = int(line.split()[1])
            except (ValueError, IndexError):
                raise FontError(f"{path}:{n}: bad char line {line!r}") from None
            rows = []
        else:
            if code is None or len(line) != cw or set(line) - {"#", "."}:
                raise FontError(f"{path}:{n}: bad glyph row {line!r} (want {cw} of '#'/'.')")
            rows.append(line)
    close(len(text))
    if not cw or not glyphs:
        raise FontError(f"{path}: no 'cell' line or no glyphs")
    return cw, ch, glyphs
