"""The parser's view of one sub-command's tokens: peek, take, expect a keyword (with the
nearest keyword for a misspelling), numbers and whole numbers with their range checks."""

from __future__ import annotations

import math

from camlab88.apps.snooker.camera.errors import CclError, did_you_mean
from camlab88.apps.snooker.camera.lexer import Token

COLOUR_WORDS = ("YELLOW", "GREEN", "BROWN", "BLUE", "PINK", "BLACK")
SUBCOMMANDS = ("FROM", "UNTIL", "OBSERVER", "VIEWPOINT", "FOCAL", "CAMERA", "COORDS")
KEYWORDS = frozenset((
    *SUBCOMMANDS, *COLOUR_WORDS, "AT", "MOVING", "TO", "FOLLOWING", "LENGTH", "OF", "FRAME",
    "CUEBALL", "CUE", "STRIKES", "ANY", "BALL", "BALLS", "STARTS", "ALL", "STOP", "STOPS",
    "END", "RED", "HITBALL", "HIT", "SPOT", "BOTTOM", "TOP", "LEFT", "RIGHT", "CENTRE",
    "POCKET",
))
PLURAL = {"START": "STARTS", "STOP": "STOPS", "STRIKE": "STRIKES", "CENTER": "CENTRE",
           "MIDDLE": "CENTRE"}


class Fail(Exception):
    def __init__(self, error: CclError) -> None:
        self.error = error


def alternatives(words: tuple[str, ...]) -> str:
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " or " + words[-1]


class Cursor:
    """The tokens of one sub-command, ending with its delimiter (or the script's end)."""

    def __init__(self, toks: list[Token]) -> None:
        self.toks = toks
        self.i = 0

    def peek(self) -> Token:
        return self.toks[self.i]

    def take(self) -> Token:
        t = self.toks[self.i]
        if self.i < len(self.toks) - 1:
            self.i += 1
        return t

    def word(self) -> str:
        t = self.peek()
        return PLURAL.get(t.upper, t.upper) if t.kind == "word" else ""

    def at(self, *words: str) -> bool:
        return self.word() in words

    def fail(self, expected: str, hints: tuple[str, ...] = ()) -> Fail:
        t = self.peek()
        hint = did_you_mean(t.text, hints or KEYWORDS) if t.kind == "word" else ""
        return Fail(CclError(t.line, t.col, f"expected {expected} but found {t.describe()}"
                                             f"{hint}"))

    def expect(self, *words: str, what: str = "") -> Token:
        if self.at(*words):
            return self.take()
        raise self.fail(what or alternatives(words), words)

    def punct(self, ch: str, what: str = "") -> Token:
        if self.peek().kind == "punct" and self.peek().text == ch:
            return self.take()
        raise self.fail(what or f"'{ch}'")

    def sign(self) -> float | None:
        t = self.peek()
        if t.kind == "punct" and t.text in "+-":
            self.take()
            return -1.0 if t.text == "-" else 1.0
        return None

    def number(self, what: str = "a number") -> tuple[float, Token]:
        start = self.peek()
        s = self.sign() or 1.0
        t = self.peek()
        if t.kind != "number":
            raise self.fail(what)
        self.take()
        v = s * float(t.text)
        if not math.isfinite(v):
            raise Fail(CclError(t.line, t.col, f"the number {t.text} is too large"))
        return v, start

    def integer(self, what: str, lo: int, hi: int | None = None) -> tuple[int, Token]:
        t = self.peek()
        if t.kind != "number":
            raise self.fail(what)
        self.take()
        if not t.text.isdigit():
            raise Fail(CclError(t.line, t.col, f"{what} must be a whole number, not {t.text}"))
        n = int(t.text)
        if n < lo or (hi is not None and n > hi):
            rng = f"{lo} to {hi}" if hi is not None else f"at least {lo}"
            raise Fail(CclError(t.line, t.col, f"{what} must be {rng}, not {n}"))
        return n, t
