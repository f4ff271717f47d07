"""How good a palette is (thesis 6.4.1's palette problem): colour error of
the 256-colour frames against the true-colour render, and flicker between frames.

error   = mean CIE76 dE, over every pixel of every frame, between what the palette shows
          and the true colour (both as the monitor shows them: 8-bit gamma-encoded);
flicker = mean dE between consecutive frames' shown colours over the pixels whose true
          colour did not change between them (a ball that stays put should not shimmer).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.render.colour import delta_e, lab
from camlab88.apps.snooker.render.gamma import decode, encode
from camlab88.apps.snooker.render.palette import Palette


@dataclass(frozen=True)
class PaletteScore:
    error: float
    flicker: float
    still_pixels: int  # pixel pairs the flicker was averaged over


def score(frames_linear: list[np.ndarray], palettes: list[Palette]) -> PaletteScore:
    """``palettes`` holds one palette per frame (or one for them all)."""
    if len(palettes) == 1:
        palettes = palettes * len(frames_linear)
    errs, flick, still = [], [], 0
    prev_true, prev_shown = None, None
    for f, pal in zip(frames_linear, palettes):
        true8 = encode(f)
        true_lab = lab(decode(true8))
        shown_lab = lab(pal.shown[pal.index(f)])
        errs.append(float(delta_e(shown_lab, true_lab).mean()))
        if prev_true is not None:
            same = np.all(true8 == prev_true, axis=2)
            if same.any():
                d = delta_e(shown_lab[same], prev_shown[same])
                flick.append(float(d.sum()))
                still += int(same.sum())
        prev_true, prev_shown = true8, shown_lab
    return PaletteScore(float(np.mean(errs)), float(np.sum(flick) / max(still, 1)), still)
