"""The picture of a whole population (``ca run --png``): the bounding box of the live cells
with a margin, which on the wrapping plane may itself cross the seam."""

from __future__ import annotations

from typing import Any

import numpy as np

from camlab88.apps.ca.engine import SIDE, Rect

MARGIN = 2  # cells round the population


def picture_rect(engine: Any, pad: int = MARGIN) -> Rect:
    """The rectangle to draw: the population's bounding box, ``pad`` cells larger (wrapping
    round the torus, or clipped to the bounded plane)."""
    box = engine.bbox() or Rect(0, 0, 0, 0)
    if engine.edges == "wrap":  # the box may cross the seam; so may the padded one
        return Rect((box.x0 - pad) % SIDE, (box.y0 - pad) % SIDE, (box.x1 + pad) % SIDE,
                    (box.y1 + pad) % SIDE)
    return Rect(max(0, box.x0 - pad), max(0, box.y0 - pad), min(SIDE - 1, box.x1 + pad),
                min(SIDE - 1, box.y1 + pad))


def picture(engine: Any, zoom: int, monochrome: bool) -> np.ndarray:
    """The population as an (h, w, 3) picture, ``zoom`` pixels a cell."""
    from camlab88.apps.ca.render import render

    return render(engine, picture_rect(engine), max(1, zoom), monochrome)
