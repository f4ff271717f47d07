"""Figure 6.8 as a screen (apps/snooker/render/antialias_figure.py): on the emulated T5688
the binary panel shows the figure's binary grid, the grey panel the renderer's coverage of
the same edge within 3 levels of the figure's greys, and the edge panel is white exactly
where the polygon covers each pixel's centre."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.render import antialias_figure as F
from camlab88.emulator.sigma import Terminal
from tests.snooker_render.test_antialias import FIG_6_8_BINARY, FIG_6_8_GREY


def _cells(screen: np.ndarray, x0: int, dx: int, dy: int) -> np.ndarray:
    """The LUT index at (dx, dy) from each cell's lower left corner, row 0 = the figure's
    top row (device y points up)."""
    out = np.zeros((4, 4), dtype=int)
    for r in range(4):
        for c in range(4):
            x, y = F._to_screen(x0, c, r + 1)
            out[r, c] = screen[y + dy, x + dx]
    return out


def test_figure_6_8_screen_shows_the_kernels_grids() -> None:
    term = Terminal("t5688")
    term.feed(F.screen())
    screen = term.indices()  # row 0 = bottom
    binary = _cells(screen, F.PANELS[1], 4, 4)
    assert (binary // 15).tolist() == FIG_6_8_BINARY.tolist()
    grey = _cells(screen, F.PANELS[2], 4, 4)
    assert np.abs(grey - FIG_6_8_GREY).max() <= 3
    assert grey.tolist() == F.grids()[1].tolist()  # the kernel's numbers, not the figure's
    centres = _cells(screen, F.PANELS[0], F.CELL // 2, F.CELL // 2)
    assert (centres == 15).astype(int).tolist() == FIG_6_8_BINARY.tolist()
