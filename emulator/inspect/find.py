"""Which device a harness target drives, and its panel."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

PANEL_WIDTH = 384  # pixels beside the screen (64 characters of the ROM font)


def _sigma_terminal(target: Any) -> Any:
    run = getattr(target, "run", None)  # a program session on a Sigma machine (KAS fronts)
    for term in (getattr(target, "term", None),
                 getattr(getattr(target, "machine", None), "terminal", None),
                 getattr(getattr(run, "machine", None), "terminal", None),
                 getattr(getattr(target, "session", None), "terminal", None)):
        if term is not None and hasattr(term, "planes") and hasattr(term, "reg"):
            return term
    return None


def _rainbow_device(target: Any) -> Any:
    device = getattr(getattr(target, "machine", None), "device", None)  # a Rainbow machine
    if device is not None and hasattr(device, "graph") and hasattr(device, "bands"):
        return device
    return None


def panel_for(target: Any) -> Callable[[np.ndarray], np.ndarray] | None:
    """A function frame -> panel (PANEL_WIDTH wide, the frame's height) for the device
    behind ``target``, or None when there is no device the inspector knows. A target whose
    device changes during the run (the demo's acts) names the one shown now by
    ``inspected()``: the panel follows it."""
    if callable(getattr(target, "inspected", None)):
        return _Following(target)
    return _panel_of(target)


class _Following:
    """The panel of whichever device ``target.inspected()`` names at each frame."""

    def __init__(self, target: Any) -> None:
        self.target = target
        self.shown: Any = None
        self.panel: Callable[[np.ndarray], np.ndarray] | None = None

    def __call__(self, frame: np.ndarray) -> np.ndarray:
        now = self.target.inspected()
        if now is not self.shown:
            self.shown, self.panel = now, None if now is None else _panel_of(now)
        return self.panel(frame) if self.panel is not None else nothing(frame.shape[0])


def nothing(height: int, why: str = "nothing to inspect here") -> np.ndarray:
    """The panel where no device is behind the picture."""
    from camlab88.emulator.inspect import draw

    img = draw.canvas(PANEL_WIDTH, height)
    draw.text(img, 8, 8, why)
    return img


def _panel_of(target: Any) -> Callable[[np.ndarray], np.ndarray] | None:
    term = _sigma_terminal(target)
    if term is not None:
        from camlab88.emulator.inspect.sigma import SigmaPanel

        return SigmaPanel(term, target.time, PANEL_WIDTH)
    device = _rainbow_device(target)
    if device is not None:
        from camlab88.emulator.inspect.rainbow import RainbowPanel

        return RainbowPanel(device, PANEL_WIDTH)
    return None
