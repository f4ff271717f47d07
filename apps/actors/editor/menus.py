"""The editor's pop-up menus, in the CA program's style: the middle button held opens the
main menu ('Do nothing' under the cursor, items highlighted as the cursor passes), its
release chooses; 'Cell type' then opens a menu of the rule set's states, where the right
button selects and Esc (or the middle button) leaves it."""

from __future__ import annotations

from camlab88.apps.actors.editor import layout as L
from camlab88.apps.actors.editor.cell_types import CellType
from camlab88.protocols.rainbow.client import RainbowClient
from camlab88.protocols.rainbow.ui import PopupMenu

MAIN = ["Do nothing", "Cell type", "Name", "Clear profile", "Remove actor", "Save", "Finish"]
MAX_TYPES = 30  # a pop-up menu's items (a 5-bit pad)


def type_label(t: CellType) -> str:
    return f"{t.state}: {t.name}"


class Menus:
    def __init__(self, client: RainbowClient) -> None:
        self.client = client
        self.main = PopupMenu(client, MAIN, lut_page=L.PAGE_MENU, priority=100)
        self.types: PopupMenu | None = None
        self.first = 0  # the state index of the types menu's first item

    def is_open(self) -> bool:
        return self.main.open_ or self.types is not None

    def choosing(self) -> bool:
        return self.types is not None

    def open_main(self, x: int, y: int) -> None:
        self.cancel()
        self.main.open(x, y)

    def close_main(self) -> str | None:
        return self.main.close() if self.main.open_ else None

    def open_types(self, types: list[CellType], current: int, x: int, y: int) -> None:
        """A menu of up to 30 cell types around the current one."""
        self.first = max(0, min(current - MAX_TYPES // 2, len(types) - MAX_TYPES))
        shown = types[self.first:self.first + MAX_TYPES]
        self.types = PopupMenu(self.client, [type_label(t) for t in shown],
                               lut_page=L.PAGE_CHOICE, visible_rows=min(len(shown), 24),
                               priority=120)
        self.types.first = current - self.first
        self.types.open(x, y)

    def track(self, x: int, y: int) -> None:
        if self.types is not None:
            self.types.track(x, y)
        elif self.main.open_:
            self.main.track(x, y)

    def chosen_type(self) -> int | None:
        """Close the types menu; the index (into the offered types) chosen, if any."""
        assert self.types is not None
        i = self.types.highlighted
        self.cancel()
        return None if i is None else self.first + i

    def cancel(self) -> None:
        if self.types is not None:
            self.types.dispose()
            self.types = None
