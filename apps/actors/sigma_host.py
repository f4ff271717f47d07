"""The period mode: the host computes each frame and sends it to a Sigma T5688 over the
9600-baud line in Sigma orders only (thesis 6.4.1's arrangement; reconstructed for actors,
docs/fidelity/ca_actors.md).

A 1987 host could not send a z-buffered picture any other way than as pixels, so: once,
graphics mode, the write and display masks and a fixed 256-colour palette in the LUT
(gamma-corrected, chosen before any frame from what the film can show: the room, the
board's two squares and the tiles under 0..4 shadows, and a ramp from dark through lit to
highlight for each actor's colour); then per frame the host's picture (the truecolour
renderer at 768 x 512) mapped to the palette, and only the pixels whose LUT index differs
from what the host knows the screen holds, as horizontal runs (snooker's RunWriter). The
first frame clears the screen with one block in the room's colour first.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.actors.render import BACKGROUND, BOARD, linear_colour
from camlab88.apps.snooker.render.gamma import GAMMA
from camlab88.apps.snooker.render.palette import SIZE, Palette
from camlab88.apps.snooker.render.runs import RunWriter
from camlab88.protocols.sigma import Encoder

SCREEN_W, SCREEN_H = 768, 512
# levels of each board square's ramp, dark to lit: at 10 the fall-off of the light across
# the board showed as a dark contour ring, and its specular highlight as a grey disc (issue
# 45); 28 levels and the glossy shades keep every step small (tested against the truecolour
# frame: tests/cafilm/test_t5688_board.py)
BOARD_LEVELS = 28
GLOSS_SHADES, GLOSS = 8, tuple(np.geomspace(0.006, 0.25, 7))  # highlight shades x white


def _ramp(albedo: np.ndarray, n: int, top: float) -> list[np.ndarray]:
    return list(albedo[None, :] * np.geomspace(0.03, top, n)[:, None])


def _board_ramp(albedo: np.ndarray, n: int, top: float) -> list[np.ndarray]:
    """The board square's shades, dark to lit, evenly spaced in drive level (gamma-encoded)
    rather than in ratio: a geometric ramp spent its levels in the dark and left steps of
    ~17 drive levels where the light squares are lit, seen as faint contour rings."""
    drive = np.linspace((0.03 / top) ** (1 / GAMMA), 1.0, n)
    return list(albedo[None, :] * (top * drive ** GAMMA)[:, None])


def _glossy(albedo: np.ndarray, top: float) -> list[np.ndarray]:
    """The board under a light's specular highlight: lit shades with white added (without
    them the highlight's pale disc was matched to the actors' greys). The shades are where
    the board is lit, 0.4 to 1 of ``top``, evenly spaced in drive level: spread in ratio
    from 0.2 of it, two of eight fell where the light squares are, and the steps between
    showed as faint contours across them."""
    lit = top * np.linspace(0.4 ** (1 / GAMMA), 1.0, GLOSS_SHADES) ** GAMMA
    return [albedo * g + s for g in lit for s in GLOSS]


def _whiten(lit: np.ndarray, n: int) -> list[np.ndarray]:
    t = np.linspace(0.0, 1.0, n + 1)[1:, None] * 0.9
    return list(np.clip(lit, 0, 1) * (1 - t) + t)


def fixed_palette(actor_colours: list[tuple[int, int, int]],
                  tile_colours: list[tuple[int, int, int]], top: float) -> Palette:
    """256 linear colours for a film whose brightest lit albedo is ``top`` times itself."""
    entries: list[np.ndarray] = [BACKGROUND]
    for f in BOARD:  # the light's fall-off across the board: steps too coarse show as rings
        entries += _board_ramp(f, BOARD_LEVELS, top) + _glossy(f, top)
    for f in (linear_colour(c) for c in tile_colours):
        entries += _ramp(f, 10, top)
    per = max(8, (SIZE - len(entries)) // max(len(actor_colours), 1) - 4)
    for c in actor_colours:
        lin = linear_colour(c)
        entries += _ramp(lin, per, top) + _whiten(lin * top, 4)
    colours = np.clip(np.array(entries), 0.0, 1.0)
    keys = np.floor(colours * 255 + 0.5).astype(np.int64) @ np.array([65536, 256, 1])
    _, first = np.unique(keys, return_index=True)
    out = colours[np.sort(first)][:SIZE]
    if len(out) < SIZE:  # greys for whatever else
        grey = np.linspace(0.0, 1.0, SIZE - len(out) + 2)[1:-1, None] * np.ones(3)
        out = np.concatenate([out, grey])
    return Palette(np.ascontiguousarray(out[:SIZE]))


@dataclass
class SentFrame:
    data: bytes
    intended: np.ndarray  # (512, 768) uint8 LUT indices the host meant, row 0 = top


class ActorsSigmaHost:
    """The host program: bytes out only (the command wires them to a T5688's line)."""

    def __init__(self, palette: Palette) -> None:
        self.palette = palette
        self.enc = Encoder(high_res=True)
        self.runs = RunWriter(self.enc, SCREEN_H)
        self.screen: np.ndarray | None = None  # what the host knows the screen shows

    def setup(self) -> bytes:
        """Graphics mode, reset, all 8 planes, quadrant 0 on screen, the palette in the LUT."""
        e = self.enc
        self.runs.forget_colour()
        return e.take_over() + e.full_colour_screen() + e.lut24_table(self.palette.lut.tolist())

    def frame(self, linear: np.ndarray) -> SentFrame:
        """The host's (512, 768, 3) linear picture -> the orders that put it on the screen."""
        if linear.shape != (SCREEN_H, SCREEN_W, 3):
            raise ValueError(f"the T5688 shows {SCREEN_W}x{SCREEN_H}, not "
                             f"{linear.shape[1]}x{linear.shape[0]}")
        idx = self.palette.index(linear)
        out = bytearray()
        if self.screen is None:
            bg = int(self.palette.index(BACKGROUND[None, :])[0])
            e = self.enc
            out += self.runs.set_colour(bg) + e.move(0, 0) + e.block(SCREEN_W - 1, SCREEN_H - 1)
            self.screen = np.full((SCREEN_H, SCREEN_W), bg, dtype=np.uint8)
        rows, xs = np.nonzero(idx != self.screen)
        out += self.runs.pixels(rows, xs, idx[rows, xs])
        self.screen = idx
        return SentFrame(bytes(out), idx.copy())
