"""Host input for a Sigma terminal: window keys are struck on the terminal's keyboard
(Terminal.press: what each sends is protocols.sigma.keyboard's table; the cursor keys move
the crosshair during a cursor read, Shift x8), the mouse is the tablet.

Window y counts rows from the top; the terminal's y axis points up, so y = 511 - row.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from camlab88.emulator.host_input import HostEvent, KeyDown, PointerButton, PointerMove
from camlab88.protocols.sigma.keyboard import KEY_BYTES

if TYPE_CHECKING:
    from camlab88.emulator.machine.sigma import SigmaMachine
    from camlab88.emulator.sigma.terminal import Terminal

KEYS_HINT = ("keys go up the line (cursor keys: the crosshair during a cursor read, Shift x8); "
             "the mouse is the tablet; close the window to quit")


def to_terminal(ev: HostEvent, term: Terminal | SigmaMachine) -> None:
    """Apply one window event to ``term``: a terminal, or a machine (its terminal's keys and
    stylus)."""
    if isinstance(ev, KeyDown):
        if ev.key in KEY_BYTES:
            term.press(ev.key, "shift" in ev.mods)
        elif ev.char:
            term.key(ev.char)
    elif isinstance(ev, PointerMove):
        term.tablet(ev.x, 511 - ev.y, False)
    elif isinstance(ev, PointerButton) and ev.pressed:
        term.tablet(ev.x, 511 - ev.y, True)
