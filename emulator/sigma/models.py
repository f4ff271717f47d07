"""The two terminal models (thesis 3.1.4, 3.3, 6.4.1; facts/sigma.md 2.1, 4.3)."""

from __future__ import annotations

from dataclasses import dataclass

SCREEN_W, SCREEN_H = 768, 512  # what the monitor shows, both models


@dataclass(frozen=True)
class Model:
    name: str
    area_w: int  # addressable drawing area
    area_h: int
    planes: int
    lut_entries: int
    gun_bits: int  # bits per LUT gun: 4 -> 4096 colours, 8 -> 16M

    @property
    def plane_mask(self) -> int:
        return (1 << self.planes) - 1

    @property
    def high_res(self) -> bool:
        """Addresses beyond 1023 (AGS extra byte, 4-digit coordinates) — the T5688's area."""
        return self.area_w > 1024


MODELS: dict[str, Model] = {
    "t5684": Model("t5684", 768, 512, 4, 16, 4),
    "t5688": Model("t5688", 1536, 1024, 8, 256, 8),
}


def get_model(name: str) -> Model:
    try:
        return MODELS[name.lower()]
    except KeyError:
        raise ValueError(f"unknown Sigma model {name!r}; choose from {', '.join(MODELS)}") from None
