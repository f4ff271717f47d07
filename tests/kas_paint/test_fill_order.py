"""Fill order decides what is in front (thesis §3.3): an area filled later hides the outlines
of the areas filled before it, on the emulated T5688, whether the frame is painted whole
(auto-paint, replay) or one command at a time (the interactive session); the outlines of
later areas, and lines no operation uses (the cel's ink), stay on top."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from camlab88.apps.kas.paint import areas
from camlab88.apps.kas.paint.ops import Op, OpsFile
from camlab88.apps.kas.paint.planes import FILL_MASK, OUTLINE_MASK
from camlab88.apps.kas.paint.program import PaintProgram
from camlab88.apps.kas.paint.session import PaintSession
from tests.kas_paint.helpers import t5688_line
from tests.kas_paint.test_kas_paint_golden import FIG_OPS, figure_38

HAT = 4  # FIG_OPS fills the hat (chains 5 and 6) in colour 4




def _at(screen: np.ndarray, points: np.ndarray) -> np.ndarray:
    px = areas.to_px(points)
    return screen[px[:, 1], px[:, 0]]


def _head_vertices(seq: AnimSequence) -> tuple[np.ndarray, np.ndarray]:
    """The head circle's vertices well inside the hat's crown, and well below its brim."""
    pts = seq.frames[0].chains[0].points
    return pts[pts[:, 1] > 1.2], pts[pts[:, 1] < 0.8]


def _painted_whole(seq: AnimSequence, ops: list[Op]) -> np.ndarray:
    prog = PaintProgram(seq, OpsFile(ops=ops))
    line, term = t5688_line()
    line.send(prog.setup())
    data, plan = prog.frame(1)
    assert plan.failures == []
    line.send(data + prog.show(areas.PAINTING.view))
    return term.indices()  # row 0 = bottom: device y


def test_later_fill_hides_earlier_outline_in_a_whole_frame() -> None:
    seq = figure_38()
    screen = _painted_whole(seq, FIG_OPS)
    under_hat, below = _head_vertices(seq)
    assert len(under_hat) >= 5 and len(below) >= 20
    hidden = _at(screen, under_hat)
    assert np.all(hidden & OUTLINE_MASK == 0), "the head's outline shows through the hat"
    assert np.all(hidden & FILL_MASK == HAT)
    assert np.all(_at(screen, below) & OUTLINE_MASK != 0), "the head lost its own outline"
    crown = seq.frames[0].chains[4].points  # the hat's own outline stays on top of it
    assert np.all(_at(screen, crown[1:-1]) & OUTLINE_MASK != 0)


def test_outline_of_an_area_filled_after_the_hat_shows_over_it() -> None:
    seq = figure_38()
    screen = _painted_whole(seq, [*FIG_OPS, Op("fill", 10, chains=(1,))])
    under_hat, _ = _head_vertices(seq)
    assert np.all(_at(screen, under_hat) & OUTLINE_MASK != 0)


def test_a_line_no_operation_uses_shows_through_any_fill() -> None:
    seq = figure_38()
    feather = Chain.from_points([(-0.5, 2.0), (0.5, 2.5)], 1)  # on the crown, never filled
    seq = AnimSequence([Drawing([*seq.frames[0].chains, feather])])
    screen = _painted_whole(seq, FIG_OPS)
    assert np.all(_at(screen, feather.points) & OUTLINE_MASK != 0)


def test_a_fill_in_colour_0_hides_no_outline() -> None:
    seq = figure_38()
    screen = _painted_whole(seq, [*FIG_OPS[:4], Op("fill", 0, chains=(5, 6))])
    under_hat, _ = _head_vertices(seq)
    assert np.all(_at(screen, under_hat) & OUTLINE_MASK != 0)


@pytest.mark.claim(
    "§3.3: the order of shading decides which areas appear in front of others",
    measured="the painting program's session on the emulated T5688: the head, then a hat "
             "filled across it; the head's outline under the hat",
    verdict="agrees: a later fill hides the outlines of the areas filled before it")
def test_interactive_fill_hides_the_outline_it_covers() -> None:
    seq = figure_38()
    s = PaintSession(seq, OpsFile())
    line, term = t5688_line()
    line.send(s.start())
    for colour, chains in ((10, [(0, -2.5)]), (HAT, [(0, 3.0), (-2.1, 1.0)])):
        s.program.current = colour
        for x, y in chains:
            line.send(s.select_near(x, y))
        line.send(s.fill())
    line.send(s.show("painting"))
    screen = term.indices()  # row 0 = bottom: device y
    under_hat, below = _head_vertices(seq)
    assert np.all(_at(screen, under_hat) & OUTLINE_MASK == 0)
    assert np.all(_at(screen, under_hat) & FILL_MASK == HAT)
    assert np.all(_at(screen, below) & OUTLINE_MASK != 0)
