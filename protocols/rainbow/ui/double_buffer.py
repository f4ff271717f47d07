"""Double buffering by two pads, one of which is on (§6.2.1, §6.3.2).

The program draws into ``back`` while ``front`` is shown; ``swap`` turns the arcs over,
so the new picture appears whole at the next frame and nothing is copied.
"""

from __future__ import annotations

from typing import Generic, TypeVar

from camlab88.base.plainstate import Int, Record
from camlab88.protocols.rainbow.attribute_state import AttributeState
from camlab88.protocols.rainbow.client import RainbowClient

T = TypeVar("T")


class Flip(AttributeState, Generic[T]):
    """Two things of which one is on screen: arc ``arcs[i]`` shows ``items[i]``, the first
    at the start."""

    def __init__(self, client: RainbowClient, items: tuple[T, T],
                 arcs: tuple[int, int]) -> None:
        self.client = client
        self.items = items
        self.arcs = arcs
        self.shown = 0
        self.swaps = 0

    @property
    def front(self) -> T:
        return self.items[self.shown]

    @property
    def back(self) -> T:
        return self.items[1 - self.shown]

    # its declared state (emulator.harness.program_state): which is shown, how many swaps
    STATE_SCHEMA = Record(shown=Int(0, 1), swaps=Int(0))

    def swap(self) -> None:
        """Show the back one, hide the front one (both take effect at the next frame)."""
        self.client.set_on(self.arcs[1 - self.shown], True)
        self.client.set_on(self.arcs[self.shown], False)
        self.shown = 1 - self.shown
        self.swaps += 1


class DoubleBuffer(Flip[int]):
    """Two pads mapped at the same place under ``parent``."""

    def __init__(self, client: RainbowClient, parent: int, width: int, height: int,
                 depth: int, plane: int = 0, lut_page: int = 0, x: int = 0, y: int = 0,
                 priority: int = 0) -> None:
        self.pads = (client.create_pad(width, height, depth, plane, lut_page),
                     client.create_pad(width, height, depth, plane, lut_page))
        super().__init__(client, self.pads,
                         (client.map(parent, self.pads[0], x, y, priority, on=True),
                          client.map(parent, self.pads[1], x, y, priority, on=False)))

    def move(self, x: int, y: int) -> None:
        for a in self.arcs:
            self.client.move(a, x, y)

    def destroy(self) -> None:
        for p in self.pads:
            self.client.destroy(p)
