"""The typed commands the decoder yields (device side) — one class per kind of thing on the wire."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

# the package (protocols.sigma) re-exports exactly these
__all__ = ["AgsEnd", "AgsEscape", "AgsPoints", "AlphaText", "Command", "DecoderStats", "Dots",
           "DotsEnd", "GraphicsFlag", "GraphicsText", "Order", "Point", "Points"]


@dataclass(frozen=True, slots=True)
class Order:
    """A two-letter order of the table with its decoded fields: Order("JG", (3, 15, 0, 0, 0))."""

    code: str
    args: tuple[int, ...] = ()


@dataclass(frozen=True, slots=True)
class GraphicsFlag:
    """``+-*/``: enter (or stay in) normal graphics mode."""


@dataclass(frozen=True, slots=True)
class Point:
    """A bare NGS coordinate pair, excess-100 already removed; moves or draws by the pen state."""

    x: int
    y: int


@dataclass(frozen=True, slots=True, eq=False)
class Points:
    """A run of two or more bare NGS pairs, (n, 2) int32 device x, y (excess-100 removed);
    each moves or draws by the pen state exactly as the same Points one by one would."""

    xy: np.ndarray

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Points) and np.array_equal(self.xy, other.xy)


@dataclass(frozen=True, slots=True, eq=False)
class AgsPoints:
    """Consecutive abbreviated-mode points, (n, 2) int32 device x, y.

    ``move_first`` is True when the first of them is the first point after ``JH`` (a move).
    """

    xy: np.ndarray
    move_first: bool

    def __eq__(self, other: object) -> bool:
        return (isinstance(other, AgsPoints) and self.move_first == other.move_first
                and np.array_equal(self.xy, other.xy))


@dataclass(frozen=True, slots=True)
class AgsEnd:
    """US: leave abbreviated mode."""


@dataclass(frozen=True, slots=True)
class AgsEscape:
    """ESC letter + 3 parameter characters inside abbreviated mode (ESC M hhh = 12-bit mask)."""

    letter: str
    param: bytes


@dataclass(frozen=True, slots=True)
class Dots:
    """Pixels of sequential dot plotting (DJ): one colour index per pixel, advancing +X."""

    colours: bytes


@dataclass(frozen=True, slots=True)
class DotsEnd:
    """Z: end of sequential dot plotting."""


@dataclass(frozen=True, slots=True)
class GraphicsText:
    """BA text (without its terminating CR)."""

    text: bytes


@dataclass(frozen=True, slots=True)
class AlphaText:
    """Bytes for the alpha screen (alpha mode), control characters included."""

    data: bytes


Command = (Order | GraphicsFlag | Point | Points | AgsPoints | AgsEnd | AgsEscape | Dots | DotsEnd
           | GraphicsText | AlphaText)


@dataclass(slots=True)
class DecoderStats:
    """What the decoder skipped: unknown orders/bytes and malformed parameters."""

    unknown: int = 0
    malformed: int = 0
    bytes_in: int = 0
    commands: int = 0
    unknown_codes: dict[str, int] = field(default_factory=dict)

    def note_unknown(self, what: str) -> None:
        self.unknown += 1
        if what in self.unknown_codes or len(self.unknown_codes) < 64:  # bounded
            self.unknown_codes[what] = self.unknown_codes.get(what, 0) + 1
