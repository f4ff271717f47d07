"""The ``sigma run --events FILE`` language: the terminal's user, scripted, for headless runs.

A UTF-8 text file, one event a line, ``#`` starts a comment (except in ``type``)::

    WHEN key NAME          a key struck: one character (A, 1, ...) or return, escape, space
    WHEN type TEXT         each character of the rest of the line struck in turn
    WHEN cursor X Y        the crosshair moved (joystick) to drawing-area X Y, device units
    WHEN tablet X Y up|down    the stylus at screen X Y (a press ends a cursor read)

``WHEN`` is when the line's user acts:

* a number ``T``: at ``T`` seconds of line time (the virtual clock of the line);
* ``reply``: once the host waits for a reply: a cursor report is armed (``HF``) and
  nothing is on its way down the line;
* ``next``: right after the event before it.

Events happen in file order: each waits for its own moment *and* for the one before it.
Bounds, so a typing error is a clear ``file:line:col`` error, never a hang: times
0..86400 s, coordinates 0..4095, at most 100000 events.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass

from camlab88.base.textinput import InputError, read_text, where

MAX_EVENTS = 100_000
MAX_TIME = 86400
COORD_MAX = 4095
KEY_NAMES = {"return": "\r", "escape": "\x1b", "space": " ", "tab": "\t",
             "backspace": "\x08", "linefeed": "\n"}
ACTIONS = ("key", "type", "cursor", "tablet")
_NUMBER = re.compile(r"[0-9]{1,5}(\.[0-9]{1,6})?")


class InputScriptError(ValueError):
    """A bad script line: ``file:line:col: what was wrong, what was expected``."""


@dataclass(frozen=True)
class ScriptEvent:
    when: str  # "at", "reply" or "next"
    at: float  # line seconds, for "at"
    action: str  # "key" (text: the characters struck), "cursor", "tablet"
    text: str = ""
    x: int = 0
    y: int = 0
    down: bool = False
    line: int = 0  # where it came from, for messages


def load(path: str | os.PathLike[str]) -> list[ScriptEvent]:
    name = os.fspath(path)
    try:
        text = read_text(name)
    except InputError as exc:
        raise InputScriptError(str(exc)) from None
    return parse(text, name)


def parse(text: str, name: str = "<events>") -> list[ScriptEvent]:
    events: list[ScriptEvent] = []
    for no, raw in enumerate(text.splitlines(), start=1):
        body = raw if raw.split()[1:2] == ["type"] else raw.split("#", 1)[0]
        words = _words(body)
        if not words:
            continue
        if len(events) >= MAX_EVENTS:
            raise InputScriptError(f"{where(name, no, 1)}: more than {MAX_EVENTS} events")
        events.append(_event(name, no, raw, words))
    return events


def _words(text: str) -> list[tuple[str, int]]:
    return [(m.group(), m.start() + 1) for m in re.finditer(r"\S+", text)]


def _event(name: str, no: int, raw: str, words: list[tuple[str, int]]) -> ScriptEvent:
    def fail(col: int, message: str) -> InputScriptError:
        return InputScriptError(f"{where(name, no, col)}: {message}")

    (when, wcol) = words[0]
    at = 0.0
    if when in ("reply", "next"):
        kind = when
    elif _NUMBER.fullmatch(when) and float(when) <= MAX_TIME:
        kind, at = "at", float(when)
    else:
        raise fail(wcol, f"expected a time in seconds (0..{MAX_TIME}), 'reply' or 'next', "
                         f"found {when[:20]!r}")
    if len(words) < 2:
        raise fail(len(raw) + 1, f"expected an action ({', '.join(ACTIONS)}) after {when!r}")
    action, acol = words[1]
    args = words[2:]
    if action == "key":
        if len(args) != 1:
            raise fail(acol, "key takes one key: a character or "
                             f"{', '.join(KEY_NAMES)}")
        key, kcol = args[0]
        char = KEY_NAMES.get(key.lower(), key if len(key) == 1 else None)
        if char is None:
            raise fail(kcol, f"unknown key {key[:20]!r} (one character or "
                             f"{', '.join(KEY_NAMES)})")
        return ScriptEvent(kind, at, "key", text=char, line=no)
    if action == "type":
        if not args:
            raise fail(acol, "type needs the text to type")
        start = raw.index("type", acol - 1) + len("type ")
        return ScriptEvent(kind, at, "key", text=raw[start:], line=no)
    if action in ("cursor", "tablet"):
        want = 2 if action == "cursor" else 3
        if len(args) != want:
            usage = "cursor X Y" if action == "cursor" else "tablet X Y up|down"
            raise fail(acol, f"expected {usage}")
        x, y = (_coord(a, fail) for a in args[:2])
        down = False
        if action == "tablet":
            state, scol = args[2]
            if state not in ("up", "down"):
                raise fail(scol, f"expected up or down, found {state[:20]!r}")
            down = state == "down"
        return ScriptEvent(kind, at, action, x=x, y=y, down=down, line=no)
    raise fail(acol, f"unknown action {action[:20]!r} (one of {', '.join(ACTIONS)})")


def _coord(word: tuple[str, int], fail) -> int:
    text, col = word
    if not re.fullmatch(r"[0-9]{1,4}", text) or int(text) > COORD_MAX:
        raise fail(col, f"expected a coordinate 0..{COORD_MAX}, found {text[:20]!r}")
    return int(text)
