"""The one event type every tablet source yields, and the model description it refers to."""

from __future__ import annotations

from dataclasses import dataclass, field, replace

TOOLS = ("pen", "eraser", "puck")


@dataclass(frozen=True)
class TabletEvent:
    """One decoded report, in the tablet's own units (no scaling, no origin flip).

    ``buttons`` is a bitmask: bit 0 is the tip (stylus) or the first puck button, bit 1 the
    first barrel/second puck button, and so on.  ``pressure`` and the tilts are ``None`` when
    the protocol (or this packet) does not carry them.  ``timestamp`` is in seconds of whatever
    clock fed the parser and does not take part in equality, so decoded events compare equal
    to the events that were encoded.
    """

    x: int
    y: int
    proximity: bool = True
    buttons: int = 0
    pressure: int | None = None
    tilt_x: int | None = None
    tilt_y: int | None = None
    tool: str = "pen"
    timestamp: float = field(default=0.0, compare=False)

    @property
    def tip(self) -> bool:
        return bool(self.buttons & 1)

    def at(self, timestamp: float) -> TabletEvent:
        return replace(self, timestamp=timestamp)

    def describe(self) -> str:
        """One monitor line: decimal tablet units, pressure, buttons, proximity."""
        parts = [
            f"x={self.x}",
            f"y={self.y}",
            f"pressure={'-' if self.pressure is None else self.pressure}",
            f"buttons={self.buttons:#06b}",
            f"prox={'in' if self.proximity else 'out'}",
            f"tool={self.tool}",
        ]
        if self.tilt_x is not None or self.tilt_y is not None:
            parts.append(f"tilt={self.tilt_x},{self.tilt_y}")
        return f"{self.timestamp:10.3f} " + " ".join(parts)


@dataclass(frozen=True)
class TabletModel:
    """What a protocol/model can report: ranges in tablet units and resolution."""

    name: str
    max_x: int
    max_y: int
    lines_per_inch: float
    pressure_max: int | None = None
    tilt_range: tuple[int, int] | None = None
    origin: str = "upper-left"  # where (0, 0) is on the tablet surface
    buttons: int = 4

    @property
    def width_inches(self) -> float:
        """0.0 when the resolution is unknown (``lines_per_inch`` 0, e.g. a HID report
        without physical units)."""
        return self.max_x / self.lines_per_inch if self.lines_per_inch > 0 else 0.0


@dataclass(frozen=True)
class DeviceReply:
    """An ASCII reply a tablet sent in answer to a query (Wacom ``~#`` etc.)."""

    text: str
    timestamp: float = field(default=0.0, compare=False)
