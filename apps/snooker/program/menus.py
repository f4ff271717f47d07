"""The two pop-up menus of §6.2.2, item for item, with their pastel colours.

Green (no ball selected) and orange (a ball selected; it scrolls). Every item has its own
pastel highlight colour, unique across both menus, which is also the background of the
message shown after the item is chosen (§6.2.1: "a pink message appears rather than a deep
green one"): position changes are pink, velocity changes green.
The item texts are the thesis's own, unabridged; the menu is as wide as its longest item
(the longest orange item, 104 characters, makes it 640 of the screen's 768 pixels).
"""

from __future__ import annotations

from camlab88.protocols.rainbow.client import RainbowClient
from camlab88.protocols.rainbow.ui import PopupMenu

ALTER_FRAME = "Alter a different frame"
EXIT = "Exit from the program"
DO_NOTHING = "Do nothing"
REPLAY = "Replay sequence at full speed"
CUE_VELOCITY = "Change the cueball's velocity"

POSITION_KEYS = "Change ball's position (by entering coordinates via the keyboard)"
VELOCITY_KEYS = "Change ball's velocity (using keyboard)"
STOP_ALL = "Stop all balls moving"
AIM_NEXT = "Aim to set up next shot"
AIM_POT = "Aim to pot this ball"
POSITION_MOUSE = "Change ball's position (by indicating new position using the mouse)"
VELOCITY_MOUSE = ("Change ball's velocity (by using the mouse to specify an arrow representing"
                  " the magnitude and direction)")

GREEN_ITEMS = [ALTER_FRAME, EXIT, DO_NOTHING, REPLAY, CUE_VELOCITY]
ORANGE_ITEMS = [POSITION_KEYS, VELOCITY_KEYS, STOP_ALL, AIM_NEXT, AIM_POT, DO_NOTHING,
                POSITION_MOUSE, VELOCITY_MOUSE]

GREEN = "#c8e4c0"  # "a light, de-saturated shade of green"
ORANGE = "#f8c890"  # "an attractive pastel orange"
ORANGE_VISIBLE_ROWS = 5  # the orange menu is larger than its window, so it scrolls

# §6.2.1: selecting a ball's position by mistake shows "a pink message ... rather than a deep
# green one": the velocity-by-mouse items are deep green (black writing still reads on it);
# the thesis calls the other highlights pastel.
DEEP_GREEN = "#30a048"
HIGHLIGHT = {
    ALTER_FRAME: "#b0d0f8",
    EXIT: "#e0e0e0",
    DO_NOTHING: "#fff8b0",
    REPLAY: "#d8c0f8",
    CUE_VELOCITY: DEEP_GREEN,
    POSITION_KEYS: "#f8c0d8",
    VELOCITY_KEYS: "#a8e8c8",
    STOP_ALL: "#f8a8a8",
    AIM_NEXT: "#a8e0f0",
    AIM_POT: "#f0d8a8",
    POSITION_MOUSE: "#f8b0c8",
    VELOCITY_MOUSE: DEEP_GREEN,
}


def green_menu(client: RainbowClient) -> PopupMenu:
    return PopupMenu(client, GREEN_ITEMS, colour=GREEN, lut_page=14,
                     highlights=[HIGHLIGHT[i] for i in GREEN_ITEMS], priority=100)


def orange_menu(client: RainbowClient) -> PopupMenu:
    return PopupMenu(client, ORANGE_ITEMS, colour=ORANGE, lut_page=15,
                     visible_rows=ORANGE_VISIBLE_ROWS,
                     highlights=[HIGHLIGHT[i] for i in ORANGE_ITEMS], priority=100)
