"""Host input events, free of pygame: what the window hands to devices and programs.

Pointer coordinates are in the device frame's pixels (unscaled): x to the right, y = frame row
(row 0 at the top). A device whose y axis points up converts them itself.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class KeyDown:
    key: str  # pygame-independent name: "a".."z", "0".."9", "space", "return", "up", "f1", ...
    char: str = ""  # the text the key typed ("" if none)
    mods: frozenset[str] = field(default_factory=frozenset)  # "shift", "ctrl", "alt", "meta"


@dataclass(frozen=True)
class KeyUp:
    key: str


@dataclass(frozen=True)
class PointerMove:
    x: int
    y: int
    buttons: frozenset[int] = field(default_factory=frozenset)  # held buttons, 1..3


@dataclass(frozen=True)
class PointerButton:
    x: int
    y: int
    button: int  # 1 left, 2 middle, 3 right
    pressed: bool


@dataclass(frozen=True)
class Quit:
    pass


HostEvent = KeyDown | KeyUp | PointerMove | PointerButton | Quit
