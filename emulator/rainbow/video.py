"""The video processor: band structure + graphics memory + lookup table -> RGB frame.

It sees nothing of the pad graph, exactly as on the hardware: whatever the band structure
says is what appears.
"""

from __future__ import annotations

import numpy as np

from camlab88.emulator.rainbow.bands import BandStructure
from camlab88.emulator.rainbow.graph import SCREEN_H, SCREEN_W

LUT_SIZE = 4096


def render(bands: BandStructure, words: np.ndarray, lut: np.ndarray,
           out: np.ndarray | None = None) -> np.ndarray:
    """The 576 x 768 x 3 frame. ``lut`` is (4096, 3) uint8."""
    if out is None:
        out = np.zeros((SCREEN_H, SCREEN_W, 3), np.uint8)
    from camlab88.emulator.rainbow._kernels import scanout  # numba: on first use

    scanout(bands.bands, bands.spans, bands.sources, words, lut, out)
    return out
