"""Turning window pointer input (or a scripted demo stroke) into tablet events."""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field

from camlab88.emulator.host_input import PointerButton, PointerMove
from camlab88.protocols.tablets.events import TabletEvent, TabletModel

# window mouse button -> tablet button bit: left = tip / button 0, right = barrel, middle = 2nd
BUTTON_BITS = {1: 1, 3: 2, 2: 4}
TIP_PRESSURE = 0.6  # fraction of full scale a mouse "presses" with (a mouse has no pressure)


def pointer_to_tablet(
    x: float, y: float, size: tuple[int, int], model: TabletModel, buttons: int,
    proximity: bool = True, tool: str = "pen",
) -> TabletEvent:
    """Window pixel (row 0 = top) -> tablet units, honouring where the tablet's origin is."""
    w, h = size
    fx = min(max(x / max(w - 1, 1), 0.0), 1.0)
    fy = min(max(y / max(h - 1, 1), 0.0), 1.0)
    if model.origin == "lower-left":
        fy = 1.0 - fy
    tx, ty = round(fx * model.max_x), round(fy * model.max_y)
    pressure = None
    if model.pressure_max is not None and tool != "puck" and proximity:
        pressure = round(model.pressure_max * TIP_PRESSURE) if buttons & 1 else 0
    return TabletEvent(tx, ty, proximity, buttons if proximity else 0, pressure, None, None, tool)


@dataclass
class PointerState:
    """Folds window pointer events into the current button mask."""

    buttons: set[int] = field(default_factory=set)
    x: int = 0
    y: int = 0

    def apply(self, event: object) -> bool:
        if isinstance(event, PointerMove):
            self.x, self.y = event.x, event.y
            self.buttons = set(event.buttons)
            return True
        if isinstance(event, PointerButton):
            self.x, self.y = event.x, event.y
            (self.buttons.add if event.pressed else self.buttons.discard)(event.button)
            return True
        return False

    @property
    def mask(self) -> int:
        return sum(BUTTON_BITS.get(b, 0) for b in set(self.buttons))


def demo_path(steps: int = 240) -> Iterator[tuple[float, float, int]]:
    """A deterministic stroke for headless runs: hover in, draw a loop and a wave, lift out.

    Yields (fx, fy, buttons) with fx, fy in 0..1 from the top-left of the surface.
    """
    hover = steps // 8
    for k in range(hover):
        yield 0.2 + 0.1 * k / hover, 0.5, 0
    loop = steps // 2
    for k in range(loop + 1):
        a = 2 * math.pi * k / loop
        yield 0.45 - 0.15 * math.cos(a), 0.5 + 0.2 * math.sin(a), 1
    wave = steps - hover - loop - 1
    for k in range(wave):
        t = k / max(wave - 1, 1)
        yield 0.3 + 0.55 * t, 0.5 + 0.15 * math.sin(6 * math.pi * t), 1
    yield 0.85, 0.5, 0
