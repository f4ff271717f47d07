"""The table-constants pop-up: §6.2 says the constants that characterise a table ("the
coefficient of friction of the table's surface, the size of the table and balls, and the
coefficient of restitution of the cushions") "may be altered by the animator"; §6.5 names
"different sizes of balls and different coefficients of restitution for the cushions".

The thesis does not say how; this third pop-up (key ``t``, in the pastel style of the green
and orange menus) is reconstructed (docs/fidelity/snooker.md).  Each item asks for its value
on the keyboard; the session applies it from the current frame on.
"""

from __future__ import annotations

from dataclasses import dataclass

from camlab88.apps.snooker.table import Table
from camlab88.protocols.rainbow.client import RainbowClient
from camlab88.protocols.rainbow.ui import PopupMenu

KEY = "t"
BALL_SIZE = "Ball size"
RESTITUTION = "Cushion restitution"
FRICTION = "Friction"
TABLE_SIZE = "Table size"
DO_NOTHING = "Do nothing"

ITEMS = [BALL_SIZE, RESTITUTION, FRICTION, TABLE_SIZE, DO_NOTHING]
COLOUR = "#c8d8f0"  # a pale pastel blue beside the green and orange menus
LUT_PAGE = 13  # pages 14 and 15 are the green and orange menus'

HIGHLIGHT = {  # pastel, none the same as a green or orange item's
    BALL_SIZE: "#f0c0f0",
    RESTITUTION: "#c0f0e8",
    FRICTION: "#e8e0b8",
    TABLE_SIZE: "#d0d0ff",
    DO_NOTHING: "#fff8b0",
}


@dataclass(frozen=True)
class Constant:
    fields: tuple[str, ...]  # Table fields, in the order they are typed
    what: str  # the prompt's words for them


CONSTANTS = {
    BALL_SIZE: Constant(("ball_diameter_m",), "Ball diameter in metres"),
    RESTITUTION: Constant(("cushion_restitution",),
                          "Cushion restitution (above 1 = cushions speed balls up)"),
    FRICTION: Constant(("deceleration_m_s2",),
                       "Friction: the cloth's deceleration of a rolling ball, m/s^2"),
    TABLE_SIZE: Constant(("length_m", "width_m"), "Table length and width in metres"),
}


def table_menu(client: RainbowClient) -> PopupMenu:
    return PopupMenu(client, ITEMS, colour=COLOUR, lut_page=LUT_PAGE,
                     highlights=[HIGHLIGHT[i] for i in ITEMS], priority=100)


def prompt(item: str, table: Table) -> str:
    c = CONSTANTS[item]
    now = " ".join(f"{getattr(table, f):g}" for f in c.fields)
    return f"{c.what}\n(now {now}; Return = keep):"


def changes(item: str, nums: list[float]) -> dict[str, float]:
    """The Table fields an entry changes; ValueError names what to type."""
    c = CONSTANTS[item]
    if len(nums) != len(c.fields):
        raise ValueError(f"type {len(c.fields)} number{'s' if len(c.fields) > 1 else ''}")
    return dict(zip(c.fields, nums))
