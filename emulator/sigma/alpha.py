"""The alpha (text) screen: 96 x 32 character cells of 8 x 16 pixels over the graphics.

The cell size and the control characters honoured are reconstructed (no public source gives
them); FF clearing the alpha screen is read from PGPLOT's "erase alpha screen" (BH FF flag).
"""

from __future__ import annotations

import numpy as np

from camlab88.emulator.sigma.models import SCREEN_H, SCREEN_W
from camlab88.roms.sigma import load_font

CELL_W, CELL_H = 8, 16
COLS, ROWS = SCREEN_W // CELL_W, SCREEN_H // CELL_H
GLYPH_TOP = 3  # first glyph row inside the cell


class AlphaScreen:
    def __init__(self) -> None:
        self.chars = np.zeros((ROWS, COLS), dtype=np.uint8)  # 0 = empty cell
        self.row = 0
        self.col = 0
        self._mask: np.ndarray | None = None

    def clear(self) -> None:
        self.chars[:] = 0
        self.row = self.col = 0
        self._mask = None

    def write(self, data: bytes) -> None:
        chars = self.chars
        for b in data:
            if 0x20 <= b <= 0x7E:
                chars[self.row, self.col] = b
                self.col += 1
                if self.col >= COLS:
                    self.col = 0
                    self._newline()
            elif b == 0x0D:
                self.col = 0
            elif b == 0x0A:
                self._newline()
            elif b == 0x08:
                self.col = max(self.col - 1, 0)
            elif b == 0x09:
                self.col = min((self.col // 8 + 1) * 8, COLS - 1)
            elif b == 0x0C:
                self.clear()
            # other control characters (NUL, BEL, XON/XOFF ...) do nothing on the screen
        self._mask = None

    # ------------------------------------------------------------------ state
    def save_state(self) -> tuple[dict[str, object], np.ndarray]:
        """(the cursor as JSON-able values, the character cells) — the screen's own state."""
        return {"row": self.row, "col": self.col}, self.chars

    @staticmethod
    def check_state(cursor: object, chars: np.ndarray) -> None:
        """ValueError unless ``cursor`` and ``chars`` are a state this screen can be in."""
        if chars.shape != (ROWS, COLS):
            raise ValueError(f"alpha cells have shape {chars.shape}, the screen is "
                             f"{(ROWS, COLS)}")
        if not (isinstance(cursor, dict) and set(cursor) == {"row", "col"}
                and all(type(v) is int for v in cursor.values())
                and 0 <= cursor["row"] < ROWS and 0 <= cursor["col"] < COLS):
            raise ValueError(f"alpha cursor {cursor!r} is not a cell of the screen")

    def load_state(self, cursor: dict[str, int], chars: np.ndarray) -> None:
        """Restore save_state()'s values (check_state them first)."""
        self.check_state(cursor, chars)
        self.chars = np.array(chars, dtype=np.uint8)
        self.row, self.col = cursor["row"], cursor["col"]
        self._mask = None

    def _newline(self) -> None:
        self.row += 1
        if self.row >= ROWS:
            self.chars[:-1] = self.chars[1:]
            self.chars[-1] = 0
            self.row = ROWS - 1

    def mask(self) -> np.ndarray:
        """(512, 768) bool, row 0 = top: the lit dots of the alpha screen."""
        if self._mask is None:
            font = load_font()
            cells = np.zeros((ROWS, COLS, CELL_H, CELL_W), dtype=bool)
            g = font.glyphs[self.chars]  # (ROWS, COLS, h, w)
            cells[:, :, GLYPH_TOP:GLYPH_TOP + font.height, 1:1 + font.width] = g
            self._mask = cells.transpose(0, 2, 1, 3).reshape(SCREEN_H, SCREEN_W)
        return self._mask
