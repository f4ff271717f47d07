"""Golden images: the four working areas of figure 3.7 (the quarter-size preview, KQ4) and a
figure-3.8-like example (a simple outline image, painted)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from camlab88.apps.kas.paint import areas
from camlab88.apps.kas.paint.ops import Op, OpsFile
from camlab88.apps.kas.paint.program import PaintProgram
from camlab88.apps.kas.paint.replay import replay
from tests.kas_paint.helpers import WALK_FILLS, t5688_line, walk
from tests.support.golden import assert_matches_golden

DATA = Path(__file__).parents[1] / "data" / "kas_paint"


def _circle(cx: float, cy: float, r: float, n: int = 24, pen: int = 1) -> Chain:
    t = np.linspace(0, 2 * np.pi, n + 1)
    return Chain.from_points(np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)]), pen)


def figure_38() -> AnimSequence:
    """A face in a hat: head, two eyes, a smile (an open chain closed by select), a hat
    whose brim crosses the head, made of two chains."""
    head = _circle(0, -0.5, 2.0, 40)
    eyes = [_circle(-0.7, 0.0, 0.3, 16, 3), _circle(0.7, 0.0, 0.3, 16, 3)]
    smile = Chain.from_points([(-1.0, -1.2), (-0.5, -1.6), (0.0, -1.75), (0.5, -1.6),
                               (1.0, -1.2)], 2)
    crown = Chain.from_points([(-1.2, 1.0), (-1.0, 3.0), (1.0, 3.0), (1.2, 1.0)])
    brim = Chain.from_points([(2.2, 1.0), (-2.2, 1.0)])
    return AnimSequence([Drawing([head, *eyes, smile, crown, brim])])


FIG_OPS = [Op("fill", 10, chains=(1,)), Op("fill", 1, chains=(2,)), Op("fill", 1, chains=(3,)),
           Op("fill", 2, chains=(4,)), Op("fill", 4, chains=(5, 6)), Op("line", 5, chains=(6,))]


@pytest.mark.claim(
    "§3.3: figure 3.8, a painted outline image",
    measured="golden image of a painted frame on the emulated T5688",
    verdict="agrees: painted in order (head, eyes, smile, hat), the hat hides the head's "
            "outline under it as §3.3's fill order says (the drawing is ours; the figure's "
            "artwork is not reproduced)")
def test_figure_38_painted_outline_image() -> None:
    line, term = t5688_line()
    prog = PaintProgram(figure_38(), OpsFile(ops=FIG_OPS))
    line.send(prog.setup())
    data, plan = prog.frame(1)
    assert plan.failures == []
    line.send(data + prog.show(areas.PAINTING.view))
    assert_matches_golden(term.frame(), DATA / "figure_3_8.png")


@pytest.mark.claim(
    "§3.3: figure 3.7, the four working areas (painting, colour mixing, two double buffers) in "
    "the T5688's drawing area four times the screen, shown at quarter size",
    measured="golden image of the emulated terminal's whole drawing area shown reduced",
    verdict="agrees")
def test_four_working_areas_quarter_size() -> None:
    seq = walk(4)
    ops = OpsFile(ops=list(WALK_FILLS), painted=2)
    line, term = t5688_line()
    prog = PaintProgram(seq, ops)
    replay(prog, line, frames=range(1, 3))           # the two double buffers
    line.send(prog.frame(3)[0] + prog.mixing_area() + prog.show(areas.PREVIEW))
    assert_matches_golden(term.frame(), DATA / "four_areas.png")
    # a palette edit shows at once in every area, nothing redrawn
    ops.palette.step(5, "blue", 200)
    sent = prog.palette_entry(5)
    assert len(sent) == 10
    line.send(sent)
    assert_matches_golden(term.frame(), DATA / "four_areas_edited.png")


def test_the_working_areas_sit_where_figure_37_puts_them() -> None:
    # figure 3.7's caption: painting bottom right, colour mixing top right, the two double
    # buffers on the left, each a quarter of the 1536 x 1024 drawing area (device y up)
    assert areas.PAINTING.origin == (768, 0) and areas.MIXING.origin == (768, 512)
    assert sorted(b.origin for b in areas.BUFFERS) == [(0, 0), (0, 512)]
    assert {a.box()[2] - a.box()[0] + 1 for a in areas.AREAS} == {768}
