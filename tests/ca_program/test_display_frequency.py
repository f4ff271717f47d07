"""§7.3.2's display frequency, through the menu and on the screen: with the display updated
every fourth generation a glider is seen translated diagonally without changing shape."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.ca.program.program import Options
from tests.ca_program.driver import Driver


def _lit(frame: np.ndarray) -> np.ndarray:
    """The pixels of the playing area in Life's living colour (green), as a bool mask."""
    return np.all(frame[:, :752] == (0, 255, 0), axis=2)


def _shape(mask: np.ndarray) -> tuple[tuple[int, int], np.ndarray]:
    ys, xs = np.nonzero(mask)
    return (int(xs.min()), int(ys.min())), mask[ys.min():ys.max() + 1, xs.min():xs.max() + 1]


@pytest.mark.claim(
    "§7.3.2: the display may be updated only every so many generations, missing out the "
    "intermediate ones; a glider shown every fourth generation is translated diagonally "
    "without changing shape",
    measured="Display frequency 4 set through the Alter display menu, then single steps: each "
             "screen shown is 4 generations on, and the glider's picture on it is the previous "
             "one's, pixel for pixel, moved one cell diagonally; at frequency 1 its shape changes",
    verdict="agrees")
def test_glider_shown_every_fourth_generation_keeps_its_shape() -> None:
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    d.main("Alter display")
    d.pick("Display frequency")
    d.type("4")
    shots = []
    for _ in range(4):
        shots.append((d.program.session.generation, _shape(_lit(d.frame))))
        d.run("click right 600 500\nframes 2")
    gens = [g for g, _ in shots]
    assert gens == [gens[0] + 4 * k for k in range(4)]
    cell = None
    for (_, (p0, s0)), (_, (p1, s1)) in zip(shots, shots[1:], strict=False):
        assert np.array_equal(s0, s1)  # the same picture
        dx, dy = p1[0] - p0[0], p1[1] - p0[1]
        assert abs(dx) == abs(dy) > 0  # moved diagonally
        cell = cell or abs(dx)
        assert abs(dx) == cell  # by one cell each time
    # every generation shown: the shape changes from one screen to the next
    d.main("Alter display")
    d.pick("Display frequency")
    d.type("1")
    before = _shape(_lit(d.frame))[1]
    d.run("click right 600 500\nframes 2")
    assert not np.array_equal(before, _shape(_lit(d.frame))[1])
