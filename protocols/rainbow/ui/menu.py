"""Pop-up menus as the thesis's programs had them (§6.2.1, §7.3.1, §7.3.2).

- Pastel items: a rectangle with a white border, black writing on the menu colour.
- The (invisible) menu cursor highlights the item under it: the item's background turns
  to its own pastel colour. Highlighting is a LUT write (each item's background has its
  own pixel value), so nothing is redrawn.
- 'Do nothing' (if present) is highlighted first and the menu opens with it under the cursor.
- A menu taller than its window scrolls: the pad moves inside a smaller clipping cluster
  when the cursor comes near the top or bottom of the visible part.
- ``CrossMenu``: five items in a cross, chosen by the direction the mouse moves.
"""

from __future__ import annotations

import colorsys
from collections.abc import Callable
from typing import Any

from camlab88.base.plainstate import Bool, Choice, Int, Opt, Record
from camlab88.protocols.rainbow.attribute_state import AttributeState
from camlab88.protocols.rainbow.client import SCREEN, SCREEN_H, SCREEN_W, RainbowClient

BORDER, INK = 0, 1  # pixel values; item i's background is 2 + i
ROW_H = 18
MARGIN = ROW_H  # how near the window's edge the cursor must come to scroll
SCROLL_STEP = 3  # pixels per cursor report: smooth, as §6.2.1 describes


def pastel(i: int, n: int, saturation: float = 0.35) -> str:
    r, g, b = colorsys.hsv_to_rgb((i / max(n, 1)) % 1.0, saturation, 1.0)
    return f"#{round(r * 255):02x}{round(g * 255):02x}{round(b * 255):02x}"


class ItemMenu:
    """What a menu of items with LUT-only highlighting does, whatever its layout: item i's
    background is pixel value 2 + i (shifted to ``plane``) on LUT page ``base`` // 256, and
    ``arc`` shows it. Subclasses draw it and set the attributes annotated here."""

    client: RainbowClient
    items: list[str]
    colour: str
    highlights: list[str]
    base: int
    plane: int
    arc: int
    highlighted: int | None
    open_: bool

    def _highlight(self, i: int | None) -> None:
        if i == self.highlighted:
            return
        if self.highlighted is not None:
            self.client.set_lut(self.base + ((2 + self.highlighted) << self.plane),
                                [self.colour])
        if i is not None:
            self.client.set_lut(self.base + ((2 + i) << self.plane), [self.highlights[i]])
        self.highlighted = i

    # its declared state (the pixels and the colours are the Rainbow's)
    STATE_SCHEMA = Record(highlighted=Opt(Int(0)), open=Bool(), scroll=Int(), x=Int(),
                          y=Int())

    def state_values(self) -> dict[str, Any]:
        return {"highlighted": self.highlighted, "open": self.open_,
                "scroll": getattr(self, "scroll", 0), "x": getattr(self, "x", 0),
                "y": getattr(self, "y", 0)}

    def check_state_values(self, values: dict[str, Any]) -> Callable[[], None]:
        h = values["highlighted"]
        if h is not None and h >= len(self.items):
            raise ValueError(f"menu item {h} of {len(self.items)}")

        def put() -> None:
            self.highlighted, self.open_ = h, values["open"]
            if hasattr(self, "scroll"):
                self.scroll, self.x, self.y = values["scroll"], values["x"], values["y"]
        return put

    def close(self) -> str | None:
        """Hide the menu; returns the item chosen (None if the cursor was off the menu)."""
        self.client.set_on(self.arc, False)
        chosen = self.highlighted
        self._highlight(None)
        self.open_ = False
        return None if chosen is None else self.items[chosen]


class PopupMenu(ItemMenu):
    def __init__(self, client: RainbowClient, items: list[str], colour: str = "#f8c890",
                 lut_page: int = 15, plane: int = 0, width: int | None = None,
                 visible_rows: int | None = None, highlights: list[str] | None = None,
                 priority: int = 100) -> None:
        self._lay_out(client, items, colour, lut_page, plane, width, visible_rows, highlights)
        self.pad = client.create_pad(self.width, self.height, 5, plane, lut_page)
        self.cluster = client.create_cluster(self.width, self.window_h)
        self.inner = client.map(self.cluster, self.pad, 0, 0)
        self.arc = client.map(SCREEN, self.cluster, 0, 0, priority, on=False)
        client.set_lut(self.base + (BORDER << plane), ["#ffffff"])
        client.set_lut(self.base + (INK << plane), ["#000000"])
        for i, item in enumerate(items):
            v = 2 + i
            client.rect(self.pad, 0, i * ROW_H, self.width, ROW_H, BORDER)
            client.rect(self.pad, 2, i * ROW_H + 2, self.width - 4, ROW_H - 4, v)
            client.text(self.pad, 8, i * ROW_H + 4, item, INK)
            client.set_lut(self.base + (v << plane), [colour])
        self.highlighted: int | None = None
        self.scroll = 0  # pad y inside the cluster (<= 0)
        self.x = self.y = 0
        self.open_ = False

    def _lay_out(self, client: RainbowClient, items: list[str], colour: str, lut_page: int,
                 plane: int, width: int | None, visible_rows: int | None,
                 highlights: list[str] | None) -> None:
        """What the menu's items and options make of it, before anything is drawn."""
        if not 1 <= len(items) <= 30:
            raise ValueError("a menu has 1..30 items (5-bit pad: 2 values + one per item)")
        self.client = client
        self.items = items
        self.colour = colour
        self.highlights = highlights or [pastel(i, len(items)) for i in range(len(items))]
        self.base = lut_page * 256
        self.plane = plane
        self.width = width or max(len(s) for s in items) * 6 + 16
        self.height = len(items) * ROW_H
        rows = min(visible_rows or len(items), len(items))
        self.window_h = rows * ROW_H
        self.first = items.index("Do nothing") if "Do nothing" in items else 0

    # A menu re-attached to what a loaded Rainbow state already holds. The pad, the
    # cluster and the two arcs are the last two nodes and arcs the client named: nothing
    # names a node while a menu is open in the programs that use this (the CA program's
    # choice menus), so they are derived, never read from a state.
    @staticmethod
    def _last_made(client: RainbowClient) -> tuple[int, int, int, int]:
        node, arc, _ = client.ids()
        return node - 2, node - 1, arc - 2, arc - 1

    def is_made_last(self) -> bool:
        """Whether this menu's pad, cluster and arcs are the last the client named (the
        menu ``reattached`` would find)."""
        return (self.pad, self.cluster, self.inner, self.arc) == self._last_made(self.client)

    @classmethod
    def reattached(cls, client: RainbowClient, items: list[str], values: dict[str, Any],
                   colour: str = "#f8c890", lut_page: int = 15, plane: int = 0,
                   width: int | None = None, visible_rows: int | None = None,
                   highlights: list[str] | None = None) -> PopupMenu:
        """The menu made last by ``client`` as a loaded Rainbow state holds it (drawn,
        placed and lit there), with its plain state ``values`` (state_values()) put back;
        nothing is sent to the device. ValueError if the values do not fit the menu."""
        menu = cls.__new__(cls)
        menu._lay_out(client, items, colour, lut_page, plane, width, visible_rows, highlights)
        menu.pad, menu.cluster, menu.inner, menu.arc = cls._last_made(client)
        if min(menu.pad, menu.inner) < 1:
            raise ValueError("the Rainbow holds no menu made last")
        menu.highlighted, menu.scroll, menu.x, menu.y, menu.open_ = None, 0, 0, 0, False
        menu.check_state_values(values)()
        return menu

    def check_state_values(self, values: dict[str, Any]) -> Callable[[], None]:
        """ItemMenu's, with the place and scroll kept to where open and track put them."""
        for name, lo, hi in (("x", 0, SCREEN_W - self.width),
                             ("y", 0, SCREEN_H - self.window_h),
                             ("scroll", self.window_h - self.height, 0)):
            if not lo <= values[name] <= max(lo, hi):
                raise ValueError(f"menu {name} {values[name]} is outside {lo}..{max(lo, hi)}")
        return super().check_state_values(values)

    def _set_scroll(self, s: int) -> None:
        s = max(min(s, 0), self.window_h - self.height)
        if s != self.scroll:
            self.scroll = s
            self.client.move(self.inner, 0, s)

    def open(self, cx: int, cy: int) -> None:
        """Pop up with the first item ('Do nothing') under the cursor at (cx, cy)."""
        row_y = self.first * ROW_H
        # scroll so the first item is inside the window, then place the window
        self._set_scroll(min(0, self.window_h - ROW_H - row_y) if row_y >= self.window_h
                         else 0)
        self.x = max(0, min(cx - self.width // 2, SCREEN_W - self.width))
        self.y = max(0, min(cy - (row_y + self.scroll) - ROW_H // 2, SCREEN_H - self.window_h))
        self.client.move(self.arc, self.x, self.y)
        self._highlight(self.first)
        self.client.set_on(self.arc, True)
        self.open_ = True

    def track(self, cx: int, cy: int) -> int | None:
        """The cursor moved to (cx, cy): scroll near the edges, highlight the item under it."""
        wy = cy - self.y
        if wy < MARGIN:
            self._set_scroll(self.scroll + SCROLL_STEP)
        elif wy >= self.window_h - MARGIN:
            self._set_scroll(self.scroll - SCROLL_STEP)
        inside = 0 <= cx - self.x < self.width and 0 <= wy < self.window_h
        self._highlight((wy - self.scroll) // ROW_H if inside else None)
        return self.highlighted

    def dispose(self) -> None:
        """Close the menu and free its pad and cluster on the device (it is not used again)."""
        self.close()
        self.client.destroy(self.pad)
        self.client.destroy(self.cluster)


class CrossMenu(AttributeState):
    """Five items in a cross (§7.3.1): centre, up, down, left, right.

    One pad per item mapped into a cluster; the cluster's empty corners show what is
    beneath. The choice depends only on the direction moved, not the distance.
    """

    DIRS = ("centre", "up", "down", "left", "right")
    CELL_W, CELL_H = 110, 24
    DEAD = 12  # pixels the mouse must move before a direction counts

    def __init__(self, client: RainbowClient, items: dict[str, str], colour: str = "#c8f0c8",
                 lut_page: int = 14, plane: int = 0, priority: int = 100) -> None:
        if set(items) != set(self.DIRS):
            raise ValueError(f"a cross menu needs exactly the items {self.DIRS}")
        self.client = client
        self.items = items
        self.colour = colour
        self.base = lut_page * 256
        self.plane = plane
        w, h = self.CELL_W, self.CELL_H
        self.cluster = client.create_cluster(3 * w, 3 * h)
        self.arc = client.map(SCREEN, self.cluster, 0, 0, priority, on=False)
        pos = {"centre": (1, 1), "up": (1, 0), "down": (1, 2), "left": (0, 1), "right": (2, 1)}
        self.pads = {}
        client.set_lut(self.base + (BORDER << plane), ["#ffffff"])
        client.set_lut(self.base + (INK << plane), ["#000000"])
        for i, d in enumerate(self.DIRS):
            pad = client.create_pad(w, h, 3, plane, lut_page)
            client.clear(pad, BORDER)
            client.rect(pad, 2, 2, w - 4, h - 4, 2 + i)
            client.text(pad, 6, 7, items[d][:17], INK)
            client.set_lut(self.base + ((2 + i) << plane), [colour])
            client.map(self.cluster, pad, pos[d][0] * w, pos[d][1] * h)
            self.pads[d] = pad
        self.highlights = {d: pastel(i, 5) for i, d in enumerate(self.DIRS)}
        self.highlighted: str | None = None
        self.cx = self.cy = 0

    # its declared state (the pixels and the colours are the Rainbow's)
    STATE_SCHEMA = Record(highlighted=Opt(Choice(DIRS)), cx=Int(), cy=Int())

    def _highlight(self, d: str | None) -> None:
        if d == self.highlighted:
            return
        for name, col in ((self.highlighted, self.colour), (d, None)):
            if name is not None:
                i = self.DIRS.index(name)
                self.client.set_lut(self.base + ((2 + i) << self.plane),
                                    [col or self.highlights[name]])
        self.highlighted = d

    def open(self, cx: int, cy: int) -> None:
        self.cx, self.cy = cx, cy
        self.client.move(self.arc, cx - 3 * self.CELL_W // 2, cy - 3 * self.CELL_H // 2)
        self._highlight("centre")
        self.client.set_on(self.arc, True)

    def track(self, x: int, y: int) -> str:
        dx, dy = x - self.cx, y - self.cy
        if max(abs(dx), abs(dy)) < self.DEAD:
            d = "centre"
        elif abs(dx) > abs(dy):
            d = "right" if dx > 0 else "left"
        else:
            d = "down" if dy > 0 else "up"
        self._highlight(d)
        return d

    def close(self) -> str:
        self.client.set_on(self.arc, False)
        d = self.highlighted or "centre"
        self._highlight(None)
        return self.items[d]
