"""CCL's lexical rules (thesis §6.3.1): anything before the first colon is a comment;
commands are delimited by colons and sub-commands by semicolons; any mixture of case; free
layout.  Tokens: words (letters only, so ``RED 8`` and ``CAMERA 3`` are two tokens each),
numbers (ASCII digits, an optional fraction and exponent; signs are separate tokens) and
the punctuation ``: ; ( ) , # + -``."""

from __future__ import annotations

import re
from dataclasses import dataclass

from camlab88.apps.snooker.camera.errors import CclError

_TOKEN = re.compile(
    r"(?P<space>[ \t\r\n\f\v]+)"
    r"|(?P<word>[A-Za-z]+)"
    r"|(?P<number>(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)"
    r"|(?P<punct>[:;(),#+\-])",
    re.ASCII,
)


@dataclass(frozen=True)
class Token:
    kind: str  # "word", "number", "punct" or "end" (the end of the script)
    text: str
    line: int
    col: int

    @property
    def upper(self) -> str:
        return self.text.upper()

    def describe(self) -> str:
        if self.kind == "end":
            return "the end of the script"
        if self.kind == "number":
            return f"the number {self.text}"
        if self.kind == "word":
            return self.text.upper()
        return f"'{self.text}'"


def _position(text: str, offset: int) -> tuple[int, int]:
    line = text.count("\n", 0, offset) + 1
    return line, offset - (text.rfind("\n", 0, offset) + 1) + 1


def tokenize(text: str) -> tuple[list[Token], list[CclError]]:
    """Tokens from the first colon on (the comment before it is dropped), ending with an
    "end" token; unreadable characters are errors and are skipped."""
    tokens: list[Token] = []
    errors: list[CclError] = []
    start = text.find(":")
    if start < 0:
        if text.strip():
            errors.append(CclError(1, 1, "no commands: everything before the first colon is a "
                                         "comment, and this script has no colon"))
        start = len(text)
    pos = start
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:
            line, col = _position(text, pos)
            errors.append(CclError(line, col, f"unexpected character {text[pos]!r}"))
            pos += 1
            continue
        if m.lastgroup != "space":
            line, col = _position(text, pos)
            tokens.append(Token(m.lastgroup or "", m.group(), line, col))
        pos = m.end()
    line, col = _position(text, len(text))
    tokens.append(Token("end", "", line, col))
    return tokens, errors
