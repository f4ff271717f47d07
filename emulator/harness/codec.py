"""Host input events (emulator.host_input) to and from the JSON objects of a recording."""

from __future__ import annotations

from typing import Any

from camlab88.emulator.host_input import HostEvent, KeyDown, KeyUp, PointerButton, PointerMove, Quit


def encode(ev: HostEvent) -> dict[str, Any]:
    """One event as a JSON object: ``{"kind": "KeyDown", "key": "a", ...}``."""
    if isinstance(ev, KeyDown):
        return {"kind": "KeyDown", "key": ev.key, "char": ev.char, "mods": sorted(ev.mods)}
    if isinstance(ev, KeyUp):
        return {"kind": "KeyUp", "key": ev.key}
    if isinstance(ev, PointerMove):
        return {"kind": "PointerMove", "x": ev.x, "y": ev.y, "buttons": sorted(ev.buttons)}
    if isinstance(ev, PointerButton):
        return {"kind": "PointerButton", "x": ev.x, "y": ev.y, "button": ev.button,
                "pressed": ev.pressed}
    if isinstance(ev, Quit):
        return {"kind": "Quit"}
    raise TypeError(f"not a host input event: {ev!r}")


def decode(obj: dict[str, Any]) -> HostEvent:
    """The event of ``encode``; a malformed object raises ValueError saying what is wrong."""
    kind = obj.get("kind")
    try:
        if kind == "KeyDown":
            return KeyDown(_s(obj["key"]), _s(obj["char"]), frozenset(map(_s, obj["mods"])))
        if kind == "KeyUp":
            return KeyUp(_s(obj["key"]))
        if kind == "PointerMove":
            return PointerMove(_i(obj["x"]), _i(obj["y"]), frozenset(map(_i, obj["buttons"])))
        if kind == "PointerButton":
            return PointerButton(_i(obj["x"]), _i(obj["y"]), _i(obj["button"]),
                                 bool(obj["pressed"]))
        if kind == "Quit":
            return Quit()
    except (KeyError, TypeError) as exc:
        raise ValueError(f"{kind} event: missing or bad field {exc}") from None
    raise ValueError(f"unknown event kind {kind!r}")


def _s(v: Any) -> str:
    if not isinstance(v, str):
        raise TypeError(repr(v))
    return v


def _i(v: Any) -> int:
    if not isinstance(v, int) or isinstance(v, bool) or not -2**31 <= v < 2**31:
        raise TypeError(repr(v))
    return v
