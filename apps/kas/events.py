"""Abstract input events that drive the KAS editor (a device front or a test script).

Pointer positions are in inches of the *screen's* twelve-field (the view), origin at the
field centre, y up - the tablet front maps tablet counts to these; the editor maps them
through its view (enlargement, panning) to the working area.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

# a script TIME's shape, checked before Fraction sees it: an exponent of many digits
# ('1e99999999999') would make Fraction compute 10**N, taking hours and gigabytes
TIME_WORD = re.compile(r"\+?(?:[0-9]{1,30}(?:\.[0-9]{0,30})?|\.[0-9]{1,30})(?:/[0-9]{1,30})?"
                       r"(?:[eE][+-]?[0-9]{1,3})?")


@dataclass(frozen=True)
class Pointer:
    x: float
    y: float
    down: bool  # stylus touching the tablet


@dataclass(frozen=True)
class Key:
    key: str  # a typed character ("u", "7", ".") or a name: space return backspace escape tab
              # up down left right f2


@dataclass(frozen=True)
class MenuPick:
    item: str  # one of editor.MENU_ITEMS


Event = Pointer | Key | MenuPick


def is_time(word: str) -> bool:
    """A script line's optional leading TIME: ``2.5`` (seconds) or ``+0.1`` (after the
    previous event)."""
    return bool(word) and word[0] in "+0123456789."


def parse_script(text: str, name: str = "<script>") -> list[Event]:
    """Events from a KAS script, one a line: ``[TIME] move X Y`` / ``down X Y`` / ``up X Y``
    / ``key K`` / ``menu ITEM`` / ``type TEXT`` (one Key per character) / ``wait``; ``#``
    comments.  This is the one KAS script format (apps/kas/program/script.py reads the same
    files on the Sigma, where TIME matters); the editor model takes the events in order, so
    TIME is checked and then ignored, and ``wait`` does nothing."""
    from camlab88.apps.kas.files import KasFileError

    out: list[Event] = []
    for no, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        word, _, rest = line.partition(" ")
        try:
            if is_time(word):
                _check_time(word)
                word, _, rest = rest.strip().partition(" ")
            if word == "wait" and not rest.strip():
                continue
            if word in ("move", "down", "up"):
                xs, ys = rest.split()
                x, y = float(xs), float(ys)
                if not (math.isfinite(x) and math.isfinite(y)):
                    raise ValueError
                out.append(Pointer(x, y, word == "down"))
            elif word == "key" and rest.strip():
                out.append(Key(rest.strip()))
            elif word == "menu" and rest.strip():
                out.append(MenuPick(rest.strip()))
            elif word == "type":
                out.extend(Key(ch if ch != " " else "space") for ch in rest)
            else:
                raise ValueError
        except ValueError:
            raise KasFileError(name, no, f"bad event {line!r} (expected [TIME] move/down/up X "
                               "Y, key K, menu ITEM, type TEXT or wait)") from None
    return out


def _check_time(word: str) -> None:
    from fractions import Fraction

    if not TIME_WORD.fullmatch(word):
        raise ValueError(word)
    try:
        v = Fraction(word[1:] if word.startswith("+") else word)
    except ZeroDivisionError:
        raise ValueError(word) from None  # ValueError: a bad line
    if not 0 <= v <= 10**6:
        raise ValueError(word)
