"""Counting the leak defect (thesis 6.4.1): "the colour inside a polygon sometimes appears on
the outside the polygon's anti-aliased boundary".

A *wrong* pixel is one whose colour on the terminal's screen is not the colour the host
program meant it to have: with every order delivered, only the firmware's line drawer —
stepping where the host's Bresenham outline did not — can make them differ. A wrong pixel
showing a polygon's fill colour is a *leak* (the thesis's defect: fill colour outside the
anti-aliased edge); the others are *gaps*, where a thin part of a polygon was cut off from
the filler by the firmware's outline and kept what was there before."""

from __future__ import annotations

import numpy as np


def leak_mask(screen: np.ndarray, intended: np.ndarray) -> np.ndarray:
    """(H, W) bool: the wrong pixels (the terminal shows a colour the host did not mean)."""
    if screen.shape != intended.shape:
        raise ValueError(f"screen {screen.shape} and intended {intended.shape} differ")
    return screen != intended


def classify(screen: np.ndarray, intended: np.ndarray,
             flat_colours: frozenset[int]) -> tuple[int, int]:
    """(leaks, gaps) among the wrong pixels."""
    wrong = leak_mask(screen, intended)
    spilled = np.isin(screen, np.array(sorted(flat_colours), dtype=np.int64)) & wrong
    n = int(np.count_nonzero(spilled))
    return n, int(np.count_nonzero(wrong)) - n
