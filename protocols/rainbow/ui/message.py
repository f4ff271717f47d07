"""Coloured message areas (§6.2.1): black writing on a rectangle of the message's colour.

The area is one 2-bit pad with its own LUT page slice: value 0 is the background (its colour
changed per message through the LUT, not by redrawing), 1 black writing, 2 a white border.
"""

from __future__ import annotations

from camlab88.base.plainstate import Record, Str
from camlab88.protocols.rainbow.attribute_state import AttributeState
from camlab88.protocols.rainbow.client import RainbowClient

PAPER, INK, BORDER = 0, 1, 2


class MessageArea(AttributeState):
    def __init__(self, client: RainbowClient, x: int, y: int, width: int, height: int,
                 lut_page: int, plane: int = 0, parent: int = 0, priority: int = 10) -> None:
        self.client = client
        self.width, self.height = width, height
        self.base = lut_page * 256
        self.plane = plane
        self.pad = client.create_pad(width, height, 2, plane, lut_page)
        self.arc = client.map(parent, self.pad, x, y, priority, on=False)
        client.set_lut(self.base + (INK << plane), ["#000000"])
        client.set_lut(self.base + (BORDER << plane), ["#ffffff"])
        self.text = ""

    # its declared state: the text shown (its pixels and colour are the Rainbow's)
    STATE_SCHEMA = Record(text=Str(65536))

    def show(self, text: str, colour: str) -> None:
        c = self.client
        c.set_lut(self.base + (PAPER << self.plane), [colour])
        c.clear(self.pad, PAPER)
        c.rect(self.pad, 0, 0, self.width, self.height, BORDER, filled=False)
        for n, line in enumerate(text.split("\n")):
            c.text(self.pad, 4, 3 + 11 * n, line, INK)
        c.set_on(self.arc, True)
        self.text = text

    def hide(self) -> None:
        self.client.set_on(self.arc, False)
        self.text = ""
