"""The default space: checkpoint units -> metres from the table's centre, spots, pockets."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.camera import space
from camlab88.apps.snooker.checkpoint import Checkpoint
from camlab88.apps.snooker.table import FOOT_M, INCH_M, Table


def test_checkpoint_units_to_default_space() -> None:
    t = Table()
    pos = np.zeros((2, 22, 2), dtype=np.int64)
    pos[0, 0] = (4096 * 6, 12544)  # the table's centre: 6 ft, 3 ft 0.75 in
    pos[0, 1] = (4096 * 12, 4096 * 0)  # top right corner
    pos[1, 2] = (-500, 100)  # behind the baulk cushion: potted
    centres, on = space.checkpoint_centres(Checkpoint(pos), t)
    assert centres.shape == (2, 22, 3)
    assert np.allclose(centres[0, 0], (0.0, 0.0, t.radius), atol=1e-15)
    assert np.allclose(centres[0, 1], (6 * FOOT_M, -6.125 / 2 * FOOT_M, t.radius))
    assert on[0, 0] and on[0, 1] and not on[1, 2]


def test_spots_and_pockets_by_hand() -> None:
    t = Table()
    hx, hy = 6 * FOOT_M, 6.125 / 2 * FOOT_M
    s = space.spots(t)
    assert np.allclose(s["pink"], (3 * FOOT_M, 0, 0))  # 3/4 of the way up from baulk
    assert np.allclose(s["blue"], (0, 0, 0))
    assert np.allclose(s["black"], (hx - 12.75 * INCH_M, 0, 0))
    assert np.allclose(s["yellow"], (-hx + 29 * INCH_M, -11.5 * INCH_M, 0))  # right of the D
    p = space.pockets(t)
    assert np.allclose(p["top left"], (hx, hy, 0)) and np.allclose(p["right centre"], (0, -hy, 0))
    assert np.allclose(p["bottom right"], (-hx, -hy, 0))
