"""Host input for the Rainbow: window events (emulator.host_input) and tablet reports
(protocols.tablets) become the Rainbow's own input events (protocols.rainbow.events)."""

from __future__ import annotations

from typing import Any

from camlab88.emulator.host_input import HostEvent, KeyDown, KeyUp, PointerButton, PointerMove
from camlab88.protocols.rainbow.events import Event, KeyEvent, MouseEvent, TabletEvent


class RainbowHostInput:
    """Converts window events to Rainbow mouse/keyboard events, keeping the held buttons
    (bits LEFT=1, MIDDLE=2, RIGHT=4) between events."""

    def __init__(self) -> None:
        self.buttons = 0

    def convert(self, ev: HostEvent) -> Event | None:
        """The Rainbow event for ``ev``, or None for what the Rainbow ignores."""
        if isinstance(ev, PointerMove):
            self.buttons = sum(1 << (b - 1) for b in ev.buttons if 1 <= b <= 3)
            return MouseEvent(0, ev.x, ev.y, self.buttons)
        if isinstance(ev, PointerButton) and 1 <= ev.button <= 3:
            bit = 1 << (ev.button - 1)
            self.buttons = self.buttons | bit if ev.pressed else self.buttons & ~bit
            return MouseEvent(0, ev.x, ev.y, self.buttons, ev.button, ev.pressed)
        if isinstance(ev, KeyDown):
            return KeyEvent(0, ev.key, ev.char, True)
        if isinstance(ev, KeyUp):
            return KeyEvent(0, ev.key, "", False)
        return None


def host_to_rainbow_event(ev: HostEvent, buttons: list[int]) -> Event | None:
    """One window event -> a Rainbow event; ``buttons[0]`` holds the held-button bits."""
    conv = RainbowHostInput()
    conv.buttons = buttons[0]
    out = conv.convert(ev)
    buttons[0] = conv.buttons
    return out


def tablet_event(ev: Any) -> TabletEvent:
    """A decoded tablet report (protocols.tablets) -> the Rainbow's tablet input event."""
    pressure = 0 if ev.pressure is None else max(0, min(int(ev.pressure), 1023))
    return TabletEvent(0, int(ev.x), int(ev.y), pressure, int(ev.buttons) & 0xFF,
                       bool(ev.proximity))
