"""The program's menus, drawn through the pad library.

- ``MainMenu``: the twenty items of section 7.3.2 in the thesis's two-column layout, pastel
  items highlighted by LUT writes as the invisible cursor passes, 'Do nothing' highlighted
  first and under the cursor; a marker to the right of the active Step mode / Auto mode.
- ``edit_menu``: the cross-shaped editing menu of section 7.3.1 (``CrossMenu``).
- ``choice_menu``: a plain pop-up (value, orientation, yes/no questions).
"""

from __future__ import annotations

from typing import Any

from camlab88.protocols.rainbow.client import SCREEN, SCREEN_H, SCREEN_W, RainbowClient
from camlab88.protocols.rainbow.ui import CrossMenu, PopupMenu
from camlab88.protocols.rainbow.ui.menu import ItemMenu, pastel

MAIN_LEFT = ["Advance area", "Alter display", "Change rules", "Clear area", "Statistics",
             "Do nothing", "Save pattern", "Load pattern", "Randomly populate", "Edit cells"]
MAIN_RIGHT = ["Centralise viewport", "Finish", "Step mode", "Auto mode", "Zoom 16", "Zoom 8",
              "Zoom 4", "Zoom 2", "Zoom 1", "Zoom subpixel"]
MAIN_ITEMS = MAIN_LEFT + MAIN_RIGHT
# Beyond the thesis: a third column for HashLife's jumps, shown when the program
# asks for it (MainMenu(..., jumps=True)); the twenty items keep their places.
JUMP_ITEMS = ["Go to generation", "Fast forward"]
EDIT_ITEMS = {"centre": "Leave editing", "up": "Step up", "down": "Step down",
              "left": "Set to value", "right": "Pick up colour"}
EDIT_MODES = {"Step up": "step_up", "Step down": "step_down", "Set to value": "set_value",
              "Pick up colour": "pick_up"}
ROW_H = 18
COL_W = 144
BORDER, INK = 0, 1  # pixel values; item i's background is 2 + i


def _cell(i: int) -> tuple[int, int]:
    return (i // 10) * COL_W, (i % 10) * ROW_H


def main_menu_origin(cx: int, cy: int, columns: int = 2) -> tuple[int, int]:
    """Where the menu opens for a middle press at (cx, cy): 'Do nothing' under the cursor,
    kept on the screen."""
    fx, fy = _cell(MAIN_ITEMS.index("Do nothing"))
    return (max(0, min(cx - fx - COL_W // 2, SCREEN_W - columns * COL_W)),
            max(0, min(cy - fy - ROW_H // 2, SCREEN_H - 10 * ROW_H)))


def main_item_point(item: str, cx: int, cy: int, jumps: bool = False) -> tuple[int, int]:
    """The centre of ``item`` in a menu opened at (cx, cy) (for scripted input)."""
    x, y = main_menu_origin(cx, cy, 3 if jumps else 2)
    ix, iy = _cell((MAIN_ITEMS + JUMP_ITEMS).index(item))
    return x + ix + COL_W // 2, y + iy + ROW_H // 2


class MainMenu(ItemMenu):
    """Two columns of ten items in one 5-bit pad (values: border, ink, one per item)."""

    def __init__(self, client: RainbowClient, lut_page: int = 15, colour: str = "#f8c890",
                 priority: int = 100, jumps: bool = False) -> None:
        self.client = client
        self.items = MAIN_ITEMS + (JUMP_ITEMS if jumps else [])
        self.columns = 3 if jumps else 2
        self.base = lut_page * 256
        self.plane = 0
        self.colour = colour
        self.highlights = [pastel(i, len(self.items)) for i in range(len(self.items))]
        self.width, self.height = self.columns * COL_W, 10 * ROW_H
        self.pad = client.create_pad(self.width, self.height, 5, 0, lut_page)
        self.arc = client.map(SCREEN, self.pad, 0, 0, priority, on=False)
        client.set_lut(self.base + BORDER, ["#ffffff"])
        client.set_lut(self.base + INK, ["#000000"])
        client.set_lut(self.base + 2, [colour] * (len(self.items) + 1))
        self.marked = ""
        for i in range(len(self.items)):
            self._draw_item(i)
        for i in range(len(self.items), 10 * self.columns):  # the third column's rest
            x, y = _cell(i)
            client.rect(self.pad, x, y, COL_W, ROW_H, 2 + len(self.items))
        self.first = MAIN_ITEMS.index("Do nothing")
        self.highlighted: int | None = None
        self.x = self.y = 0
        self.open_ = False

    def _draw_item(self, i: int) -> None:
        x, y = _cell(i)
        c = self.client
        c.rect(self.pad, x, y, COL_W, ROW_H, BORDER)
        c.rect(self.pad, x + 2, y + 2, COL_W - 4, ROW_H - 4, 2 + i)
        c.text(self.pad, x + 8, y + 4, self.items[i], INK)
        if self.items[i] == self.marked:
            c.text(self.pad, x + COL_W - 14, y + 4, "<", INK)

    def mark(self, item: str) -> None:
        """Show which of Step mode / Auto mode / Fast forward is active (a marker right of
        the item)."""
        old, self.marked = self.marked, item
        for name in (old, item):
            if name in self.items:
                self._draw_item(self.items.index(name))

    def open(self, cx: int, cy: int) -> None:
        self.x, self.y = main_menu_origin(cx, cy, self.columns)
        self.client.move(self.arc, self.x, self.y)
        self._highlight(self.first)
        self.client.set_on(self.arc, True)
        self.open_ = True

    def track(self, cx: int, cy: int) -> str | None:
        dx, dy = cx - self.x, cy - self.y
        inside = 0 <= dx < self.width and 0 <= dy < self.height
        i = (dx // COL_W) * 10 + dy // ROW_H if inside else None
        self._highlight(i if i is not None and i < len(self.items) else None)
        return None if self.highlighted is None else self.items[self.highlighted]



def edit_menu(client: RainbowClient) -> CrossMenu:
    return CrossMenu(client, EDIT_ITEMS, lut_page=14, priority=110)


CHOICE_PAGE = 13  # the LUT page of a dialogue's choice menu


def choice_menu(client: RainbowClient, items: list[str]) -> PopupMenu:
    rows = min(len(items), 24)
    return PopupMenu(client, items, lut_page=CHOICE_PAGE, visible_rows=rows, priority=120)


def choice_menu_reattached(client: RainbowClient, items: list[str],
                           values: dict[str, Any]) -> PopupMenu:
    """``choice_menu(client, items)`` as a loaded Rainbow state already holds it (the last
    menu made), with its plain state ``values`` put back (a saved dialogue's open menu)."""
    rows = min(len(items), 24)
    return PopupMenu.reattached(client, items, values, lut_page=CHOICE_PAGE, visible_rows=rows)
