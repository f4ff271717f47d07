"""Event-script helpers for driving the editor model in tests."""

from __future__ import annotations

from camlab88.apps.kas.events import Key, Pointer


def tap(x: float, y: float) -> list:
    """Stylus hover, touch and lift at (x, y)."""
    return [Pointer(x, y, False), Pointer(x, y, True), Pointer(x, y, False)]


def typed(text: str) -> list:
    return [Key(c) for c in text] + [Key("return")]


def keys(*names: str) -> list:
    return [Key(n) for n in names]


def pts(ed, i: int) -> list:
    return ed.drawing.chains[i].points.round(9).tolist()
