"""Input events the Rainbow delivers to a program: 3-button mouse, keyboard, tablet.

Timestamps are the device's own clock in milliseconds (it advances 20 ms a frame at 50 Hz),
so a recorded session replays to the same events. Each event has a fixed binary form used
in replies to ``poll_events`` and in recordings.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass

LEFT, MIDDLE, RIGHT = 1, 2, 4  # button bits in ``buttons``


@dataclass(frozen=True)
class MouseEvent:
    """``button`` 0 = the mouse moved; else the button (1 left, 2 middle, 3 right) changed."""

    t_ms: int
    x: int
    y: int
    buttons: int  # bit set of buttons held after the event: LEFT | MIDDLE | RIGHT
    button: int = 0
    pressed: bool = False


@dataclass(frozen=True)
class KeyEvent:
    t_ms: int
    key: str  # device-neutral name: "a", "space", "return", "up", ...
    char: str  # the typed text, "" if none
    pressed: bool = True


@dataclass(frozen=True)
class TabletEvent:
    t_ms: int
    x: int
    y: int
    pressure: int  # 0..1023
    buttons: int
    proximity: bool = True


Event = MouseEvent | KeyEvent | TabletEvent

_MOUSE = struct.Struct("<BqiiBBB")
_KEY = struct.Struct("<BqBHH")  # kind, t, pressed, len(key), len(char) + utf-8 text
_TABLET = struct.Struct("<BqiiHBB")


class EventFormatError(ValueError):
    pass


def encode_event(e: Event) -> bytes:
    if isinstance(e, MouseEvent):
        return _MOUSE.pack(1, e.t_ms, e.x, e.y, e.buttons, e.button, e.pressed)
    if isinstance(e, KeyEvent):
        k, c = e.key.encode(), e.char.encode()
        return _KEY.pack(2, e.t_ms, e.pressed, len(k), len(c)) + k + c
    if isinstance(e, TabletEvent):
        return _TABLET.pack(3, e.t_ms, e.x, e.y, e.pressure, e.buttons, e.proximity)
    raise TypeError(f"not an input event: {e!r}")


def decode_events(data: bytes, where: str = "events") -> list[Event]:
    out: list[Event] = []
    pos = 0
    try:
        while pos < len(data):
            kind = data[pos]
            if kind == 1:
                _, t, x, y, b, btn, p = _MOUSE.unpack_from(data, pos)
                out.append(MouseEvent(t, x, y, b, btn, bool(p)))
                pos += _MOUSE.size
            elif kind == 2:
                _, t, p, lk, lc = _KEY.unpack_from(data, pos)
                pos += _KEY.size
                if pos + lk + lc > len(data):
                    raise struct.error("key text runs past the end")
                k = data[pos: pos + lk].decode()
                c = data[pos + lk: pos + lk + lc].decode()
                pos += lk + lc
                out.append(KeyEvent(t, k, c, bool(p)))
            elif kind == 3:
                _, t, x, y, pr, b, prox = _TABLET.unpack_from(data, pos)
                out.append(TabletEvent(t, x, y, pr, b, bool(prox)))
                pos += _TABLET.size
            else:
                raise EventFormatError(f"{where}: byte {pos}: unknown event kind {kind}")
    except (struct.error, UnicodeDecodeError) as exc:
        raise EventFormatError(f"{where}: byte {pos}: truncated or bad event ({exc})") from None
    return out
