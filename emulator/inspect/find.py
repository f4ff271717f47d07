"""Which device a harness target drives, and its panel."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

PANEL_WIDTH = 384  # pixels beside the screen (64 characters of the ROM font)


def _sigma_terminal(target: Any) -> Any:
    for term in (getattr(target, "term", None),
                 getattr(getattr(target, "machine", None), "terminal", None),
                 getattr(getattr(target, "session", None), "terminal", None)):
        if term is not None and hasattr(term, "planes") and hasattr(term, "reg"):
            return term
    return None


def _rainbow_device(target: Any) -> Any:
    device = getattr(getattr(target, "session", None), "device", None)
    if device is not None and hasattr(device, "graph") and hasattr(device, "bands"):
        return device
    return None


def panel_for(target: Any) -> Callable[[np.ndarray], np.ndarray] | None:
    """A function frame -> panel (PANEL_WIDTH wide, the frame's height) for the device
    behind ``target``, or None when there is no device the inspector knows."""
    term = _sigma_terminal(target)
    if term is not None:
        from camlab88.emulator.inspect.sigma import SigmaPanel

        return SigmaPanel(term, target.time, PANEL_WIDTH)
    device = _rainbow_device(target)
    if device is not None:
        from camlab88.emulator.inspect.rainbow import RainbowPanel

        return RainbowPanel(device, PANEL_WIDTH)
    return None
