"""Host input for a Sigma terminal: window keys are typed on the terminal's keyboard (they go
up the line), the cursor keys move the crosshair (Shift: 8 pixels), the mouse is the tablet.

Window y counts rows from the top; the terminal's y axis points up, so y = 511 - row.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from camlab88.emulator.host_input import HostEvent, KeyDown, PointerButton, PointerMove

if TYPE_CHECKING:
    from camlab88.emulator.sigma.terminal import Terminal

KEY_CHARS = {"return": "\r", "kp_enter": "\r", "backspace": "\b", "escape": "\x1b",
             "tab": "\t", "delete": "\x7f"}
ARROWS = {"left": (-1, 0), "right": (1, 0), "up": (0, 1), "down": (0, -1)}
KEYS_HINT = ("keys go up the line; cursor keys move the crosshair (Shift x8); the mouse is "
             "the tablet; close the window to quit")


def to_terminal(ev: HostEvent, term: Terminal) -> None:
    """Apply one window event to terminal ``term``."""
    if isinstance(ev, KeyDown):
        if ev.key in ARROWS:
            dx, dy = ARROWS[ev.key]
            step = 8 if "shift" in ev.mods else 1
            term.cursor_keys(dx * step, dy * step)
        elif ev.char:
            term.key(ev.char)
        elif ev.key in KEY_CHARS:
            term.key(KEY_CHARS[ev.key])
    elif isinstance(ev, PointerMove):
        term.tablet(ev.x, 511 - ev.y, False)
    elif isinstance(ev, PointerButton) and ev.pressed:
        term.tablet(ev.x, 511 - ev.y, True)
