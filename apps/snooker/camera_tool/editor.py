"""The script being edited: lines of text and a cursor, with the few edits a plain text
editor offers (insert, backspace, delete, newline, cursor keys)."""

from __future__ import annotations


class TextBuffer:
    def __init__(self, text: str = "") -> None:
        self.lines = text.split("\n")
        self.line = 0
        self.col = 0

    @property
    def text(self) -> str:
        return "\n".join(self.lines)

    def replace(self, text: str) -> None:
        """New text (reloaded from disk); the cursor stays where it can."""
        self.lines = text.split("\n")
        self.line = min(self.line, len(self.lines) - 1)
        self.col = min(self.col, len(self.lines[self.line]))

    def insert(self, s: str) -> None:
        for part in s.split("\n")[:-1]:
            self._insert_text(part)
            self.newline()
        self._insert_text(s.split("\n")[-1])

    def _insert_text(self, s: str) -> None:
        row = self.lines[self.line]
        self.lines[self.line] = row[: self.col] + s + row[self.col:]
        self.col += len(s)

    def newline(self) -> None:
        row = self.lines[self.line]
        self.lines[self.line: self.line + 1] = [row[: self.col], row[self.col:]]
        self.line += 1
        self.col = 0

    def backspace(self) -> None:
        if self.col > 0:
            row = self.lines[self.line]
            self.lines[self.line] = row[: self.col - 1] + row[self.col:]
            self.col -= 1
        elif self.line > 0:
            self.col = len(self.lines[self.line - 1])
            self.lines[self.line - 1: self.line + 1] = [self.lines[self.line - 1]
                                                        + self.lines[self.line]]
            self.line -= 1

    def delete(self) -> None:
        if self.col < len(self.lines[self.line]) or self.line < len(self.lines) - 1:
            self.move(0, 1)
            self.backspace()

    def move(self, dline: int, dcol: int) -> None:
        """Cursor keys: left/right wrap round line ends; up/down keep the column if they can."""
        if dcol:
            self.col += dcol
            if self.col < 0 and self.line > 0:
                self.line -= 1
                self.col = len(self.lines[self.line])
            elif self.col > len(self.lines[self.line]) and self.line < len(self.lines) - 1:
                self.line += 1
                self.col = 0
        self.line = max(0, min(len(self.lines) - 1, self.line + dline))
        self.col = max(0, min(len(self.lines[self.line]), self.col))

    def home(self) -> None:
        self.col = 0

    def end(self) -> None:
        self.col = len(self.lines[self.line])

    def place(self, line: int, col: int) -> None:
        self.line = max(0, min(len(self.lines) - 1, line))
        self.col = max(0, min(len(self.lines[self.line]), col))
