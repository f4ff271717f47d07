"""The painting palette (thesis §3.3): up to 32 fill colours per sequence, a default palette,
and the two ways of editing an entry — mixing already defined colours, and the RGB editor
that shows the current proportions and changes them step by step (any of the 16M colours).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from camlab88.apps.kas.paint.planes import MAX_FILL_COLOURS, RGB

# Reconstructed: the thesis gives no default palette.  Entry 0 is the unpainted paper
# (black, like KAS's drawing background); then flat cartoon colours, light and dark pairs.
DEFAULT: tuple[RGB, ...] = (
    (0, 0, 0), (255, 255, 255), (220, 30, 30), (30, 160, 60), (40, 80, 220),
    (250, 220, 40), (40, 200, 220), (210, 60, 200), (250, 150, 30), (140, 90, 40),
    (255, 200, 170), (128, 128, 128), (255, 140, 140), (150, 230, 140), (150, 180, 255),
    (255, 245, 160), (120, 0, 0), (0, 80, 20), (0, 20, 100), (150, 120, 0),
    (0, 110, 120), (100, 0, 100), (160, 80, 0), (70, 40, 20), (200, 150, 110),
    (64, 64, 64), (192, 192, 192), (255, 100, 0), (170, 255, 0), (0, 255, 160),
    (90, 0, 255), (255, 0, 120),
)
GUNS = ("red", "green", "blue")


@dataclass
class Palette:
    """Entries 0..n-1 of (r, g, b), 8 bits a gun; entry 0 is the unpainted background."""

    entries: list[RGB] = field(default_factory=lambda: list(DEFAULT))

    def __post_init__(self) -> None:
        if not 1 <= len(self.entries) <= MAX_FILL_COLOURS:
            raise ValueError(f"a palette has 1 to {MAX_FILL_COLOURS} entries")
        self.entries = [_check(c) for c in self.entries]

    def __len__(self) -> int:
        return len(self.entries)

    def __getitem__(self, i: int) -> RGB:
        return self.entries[i]

    def set(self, i: int, rgb: RGB) -> None:
        self._index(i)
        self.entries[i] = _check(rgb)

    def mix(self, target: int, parts: dict[int, int]) -> RGB:
        """Entry ``target`` := the mixture of other entries, ``parts`` {entry: amount}."""
        total = sum(parts.values())
        if total <= 0 or any(v < 0 for v in parts.values()):
            raise ValueError("mix amounts must be positive")
        for i in parts:
            self._index(i)
        rgb = tuple(round(sum(self.entries[i][g] * n for i, n in parts.items()) / total)
                    for g in range(3))
        self.set(target, rgb)
        return self.entries[target]

    def step(self, i: int, gun: str, delta: int) -> RGB:
        """The RGB editor: change one gun of entry ``i`` by ``delta`` (clamped 0..255)."""
        if gun not in GUNS:
            raise ValueError(f"gun is one of {', '.join(GUNS)}, not {gun!r}")
        rgb = list(self.entries[self._index(i)])
        g = GUNS.index(gun)
        rgb[g] = min(max(rgb[g] + int(delta), 0), 255)
        self.entries[i] = tuple(rgb)
        return self.entries[i]

    def proportions(self, i: int) -> tuple[float, float, float]:
        """What the RGB editor shows: each gun as a fraction of full intensity."""
        return tuple(v / 255 for v in self.entries[self._index(i)])

    def _index(self, i: int) -> int:
        if not 0 <= i < len(self.entries):
            raise ValueError(f"colour {i} is not in the palette (0..{len(self.entries) - 1})")
        return i


def _check(rgb: RGB) -> RGB:
    t = tuple(int(v) for v in rgb)
    if len(t) != 3 or any(not 0 <= v <= 255 for v in t):
        raise ValueError(f"a colour is three values 0..255, not {rgb!r}")
    return t
