"""The wrapping plane's seam (x = 65535 | 0): bounding box, rectangles dragged across it,
clearing, advance areas, random population, saving and centralising."""

from __future__ import annotations

from camlab88.apps.ca import log
from camlab88.apps.ca.engine import SIDE, Engine, Rect
from camlab88.apps.ca.program.commands import rect_from
from camlab88.apps.ca.session import Session
from tests.ca.helpers import LIFE, cellset, shifted

GLIDER = ".O.\n..O\nOOO"


def life(cells: str, x0: int, y0: int, **kw) -> Engine:
    """Life with ``cells`` drawn from (x0, y0), wrapping round the plane."""
    e = Engine(LIFE, **kw)
    pts = [((x0 + x) % SIDE, (y0 + y) % SIDE) for y, row in enumerate(cells.splitlines())
           for x, ch in enumerate(row) if ch == "O"]
    e.set_cells([p[0] for p in pts], [p[1] for p in pts], 1)
    return e


def test_bbox_of_a_glider_on_the_seam_is_small() -> None:
    e = life(GLIDER, SIDE - 2, 100)  # columns 65534, 65535, 0
    box = e.bbox()
    assert box is not None and (box.x0, box.x1, box.y0, box.y1) == (SIDE - 2, 0, 100, 102)
    assert (box.width, box.height) == (3, 3) and box.wraps
    assert e.stats()["bbox"] == [SIDE - 2, 100, 0, 102]
    both = life(GLIDER, SIDE - 1, SIDE - 1)  # across both seams: the corner
    b = both.bbox()
    assert b is not None and (b.width, b.height) == (3, 3)
    far = life(GLIDER, 30000, 100)  # not near the seam: plain min..max
    assert far.bbox() == Rect(30000, 100, 30002, 102)
    bounded = life("O", 0, 5, edges="bounded")
    bounded.set(SIDE - 1, 5, 1)
    assert bounded.bbox() == Rect(0, 5, SIDE - 1, 5)  # a bounded plane has no seam


def test_centralise_on_a_glider_on_the_seam() -> None:
    s = Session(life(GLIDER, SIDE - 2, 100))
    s.centralise(47, 36)
    assert (s.view.x, s.view.y) == ((SIDE - 1 - 23) % SIDE, 101 - 18)


def test_rectangle_dragged_across_the_seam_and_clearing_it() -> None:
    r = rect_from((65530, 100), (5, 110))
    assert (r.x0, r.y0, r.x1, r.y1) == (65530, 100, 5, 110)
    assert (r.width, r.height) == (12, 11)
    assert rect_from((5, 110), (65530, 100)) == r  # either corner first
    assert rect_from((10, 20), (3, 4)) == Rect(3, 4, 10, 20)
    e = Engine(LIFE)
    e.set_cells([65529, 65530, 65535, 0, 5, 6, 30000], [105] * 7, 1)
    xs, _, _ = e.cells_in_rect(r)
    assert sorted(xs.tolist()) == [0, 5, 65530, 65535]
    e.clear(r)
    assert sorted(e.xs.tolist()) == [6, 30000, 65529]


def test_advance_area_across_the_seam() -> None:
    e = life(GLIDER, SIDE - 2, 100)
    e.set(30000, 100, 1)  # outside: frozen (a lone cell would die)
    start = cellset(life(GLIDER, SIDE - 2, 100))
    e.set_advance_area(rect_from((SIDE - 20, 90), (20, 130)))
    e.step(8)
    assert cellset(e) == shifted(start, 2, 2) | {(30000, 100, 1)}
    assert e.advance_area == Rect(SIDE - 20, 90, 20, 130)


def test_random_population_across_the_seam_stays_inside() -> None:
    e = Engine(LIFE)
    r = rect_from((SIDE - 4, 10), (3, 13))
    log.populate(e, r, 1.0, {1: 1.0}, seed=1)
    assert e.population == 8 * 4
    assert set(e.xs.tolist()) == {SIDE - 4, SIDE - 3, SIDE - 2, SIDE - 1, 0, 1, 2, 3}
