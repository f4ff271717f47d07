"""Counting the leak defect (thesis 6.4.1): "the colour inside a polygon sometimes appears on
the outside the polygon's anti-aliased boundary". A leaking pixel is one whose colour on the
terminal's screen is not the colour the host program meant it to have: with every order
delivered, only the firmware's line drawer — stepping where the host's Bresenham outline
did not — can make them differ."""

from __future__ import annotations

import numpy as np


def leak_mask(screen: np.ndarray, intended: np.ndarray) -> np.ndarray:
    """(H, W) bool: pixels the terminal shows in a colour the host did not mean."""
    if screen.shape != intended.shape:
        raise ValueError(f"screen {screen.shape} and intended {intended.shape} differ")
    return screen != intended


def count_leaks(screen: np.ndarray, intended: np.ndarray) -> int:
    return int(np.count_nonzero(leak_mask(screen, intended)))
