"""The colour and material sliders (one 4-bit pad): red, green, blue 0..255 and the Phong
material's ambient, diffuse, specular 0..1 and shininess 1..200. The left button pressed or
dragged on a row sets that row's value from the x position; a swatch shows the colour."""

from __future__ import annotations

from dataclasses import dataclass

from camlab88.protocols.rainbow.client import RainbowClient


@dataclass(frozen=True)
class Slider:
    name: str
    low: float
    high: float
    step: float  # values snap to it, so a saved file holds short numbers


SLIDERS = (Slider("Red", 0, 255, 1), Slider("Green", 0, 255, 1), Slider("Blue", 0, 255, 1),
           Slider("Ambient", 0, 1, 0.01), Slider("Diffuse", 0, 1, 0.01),
           Slider("Specular", 0, 1, 0.01), Slider("Shininess", 1, 200, 1))
ROW_H = 20
LABEL_W = 72
TRACK_X, TRACK_W = LABEL_W, 200
SWATCH = (304, 4, 60, 60)
PAPER, INK, TRACK, FILL, SWATCH_V = 0, 1, 2, 3, 4
COLOURS = {PAPER: "#283040", INK: "#e8e8e8", TRACK: "#586070", FILL: "#f8c890"}


def value_at(s: Slider, x: int) -> float:
    """The value for a press at pad x (clamped to the track)."""
    f = min(max((x - TRACK_X) / (TRACK_W - 1), 0.0), 1.0)
    v = s.low + f * (s.high - s.low)
    n = round((v - s.low) / s.step)
    return round(s.low + n * s.step, 2)


def row_at(y: int) -> int | None:
    r = (y - 2) // ROW_H
    return r if 0 <= r < len(SLIDERS) and y >= 2 else None


def _text(v: float, s: Slider) -> str:
    return f"{v:.0f}" if s.step >= 1 else f"{v:.2f}"


class SliderPad:
    def __init__(self, client: RainbowClient, rect: tuple[int, int, int, int],
                 lut_page: int) -> None:
        self.client = client
        x, y, w, h = rect
        self.base = lut_page * 256
        self.pad = client.create_pad(w, h, 4, 0, lut_page)
        client.map(0, self.pad, x, y, 5)
        client.set_lut(self.base, [COLOURS[PAPER], COLOURS[INK], COLOURS[TRACK], COLOURS[FILL],
                                   "#000000"])
        client.clear(self.pad, PAPER)
        self.values: list[float] = [s.low for s in SLIDERS]
        self.drawn = False

    def show(self, values: list[float]) -> None:
        """Redraw the rows whose values changed, and the swatch."""
        for i, v in enumerate(values):
            if v != self.values[i] or not self.drawn:
                self._row(i, v)
        self.drawn = True
        self.values = list(values)
        r, g, b = (int(v) for v in values[:3])
        self.client.set_lut(self.base + SWATCH_V, [(r, g, b)])
        sx, sy, sw, sh = SWATCH
        self.client.rect(self.pad, sx, sy, sw, sh, INK, filled=False)
        self.client.rect(self.pad, sx + 2, sy + 2, sw - 4, sh - 4, SWATCH_V)

    def _row(self, i: int, v: float) -> None:
        c, s = self.client, SLIDERS[i]
        y = 2 + i * ROW_H
        c.rect(self.pad, 0, y, SWATCH[0] - 4, ROW_H, PAPER)
        c.text(self.pad, 4, y + 5, s.name, INK)
        c.rect(self.pad, TRACK_X, y + 4, TRACK_W, ROW_H - 8, TRACK)
        f = min(max((v - s.low) / (s.high - s.low), 0.0), 1.0)  # a file may go beyond
        c.rect(self.pad, TRACK_X, y + 4, max(1, round(f * TRACK_W)), ROW_H - 8, FILL)
        c.text(self.pad, TRACK_X + TRACK_W + 4, y + 5, _text(v, s), INK)
