"""Typing an actor's name on the message pad (pure): Return sets it, Esc leaves it as it was,
Backspace rubs out; only the actors file's name characters are taken (letters, digits,
``_ . + -``, at most 64, starting with a letter, digit or ``_``)."""

from __future__ import annotations

from camlab88.apps.actors.model import NAME

ALLOWED = set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.+-")
MAX_LEN = 64


class NameEntry:
    def __init__(self, name: str) -> None:
        self.text = name
        self.fresh = True  # the first character typed replaces the offered name

    def key(self, key: str, char: str) -> str:
        """One key: "set" (``text`` is a good name), "cancel", "bad" (Return on a name the
        file would refuse) or "typing"."""
        if key in ("return", "enter", "kp_enter"):
            return "set" if NAME.match(self.text) else "bad"
        if key == "escape":
            return "cancel"
        if key == "backspace":
            self.text, self.fresh = self.text[:-1], False
        elif char in ALLOWED and char:
            self.text = ("" if self.fresh else self.text)[:MAX_LEN - 1] + char
            self.fresh = False
        return "typing"
