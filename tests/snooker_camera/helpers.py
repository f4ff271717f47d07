"""A small synthetic motion for CCL tests: every number in it is chosen by hand."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.camera.motion import Motion
from camlab88.apps.snooker.table import Table

T = Table()
R = T.radius
OFF = np.array([9.0, 9.0, R])  # where potted balls sit in these tests


def still(frames: int = 20) -> np.ndarray:
    """Every ball at rest: ball i at (0.1 i - 1, 0.02 i, R); reds 1..15 are balls 7..21."""
    c = np.zeros((frames, 22, 3))
    for i in range(22):
        c[:, i] = (0.1 * i - 1.0, 0.02 * i, R)
    return c


def make(centres: np.ndarray, strikes: tuple[tuple[int, int], ...] = ()) -> Motion:
    hx, hy = T.length_m / 2, T.width_m / 2
    on = (np.abs(centres[..., 0]) <= hx) & (np.abs(centres[..., 1]) <= hy)
    return Motion(T, centres, on, strikes)


def pink_rolls(first: int = 5, last: int = 12, frames: int = 20) -> Motion:
    """The pink (ball 5) moves 0.01 m in +x into each frame first..last; the cue ball
    strikes it at `first`."""
    c = still(frames)
    for f in range(first, last + 1):
        c[f - 1:, 5, 0] += 0.01
    return make(c, ((first, 5),))
