from __future__ import annotations

from pathlib import Path

import numpy as np

from camlab88.apps.actors.model import Actor, Material, Part, read_actors
from camlab88.apps.actors.preview import turntable

CHESS = Path(__file__).resolve().parents[2] / "examples" / "ca" / "chess.actors"


def _knight() -> Actor:
    return read_actors(CHESS).actors[2]


def test_turntable_is_an_rgb_picture_of_the_asked_size_and_deterministic() -> None:
    a = turntable(_knight(), 30.0, (96, 64))
    assert a.shape == (64, 96, 3) and a.dtype == np.uint8
    assert np.array_equal(a, turntable(_knight(), 30.0, (96, 64)))


def test_turning_an_asymmetric_actor_changes_the_picture_a_full_turn_does_not() -> None:
    a, b = turntable(_knight(), 0.0, (80, 80)), turntable(_knight(), 90.0, (80, 80))
    assert np.count_nonzero(np.any(a != b, axis=2)) > 50
    full = turntable(_knight(), 360.0, (80, 80))
    assert np.count_nonzero(np.any(a.astype(int) - full > 1, axis=2)) < 5


def test_the_actor_shows_in_its_colour_in_the_middle_of_the_picture() -> None:
    red = Actor(1, "drum", (220, 20, 20), Material(1.0, 0.8, 0.0, 1.0),
                (Part("lathe", ((0.4, 0.0), (0.4, 0.8))),))
    img = turntable(red, 0.0, (64, 64)).astype(int)
    mid = img[24:40, 26:38].reshape(-1, 3)
    assert np.all(mid[:, 0] > mid[:, 1] + 40) and np.all(mid[:, 0] > mid[:, 2] + 40)
    corner = img[:6, :6].reshape(-1, 3)
    assert not np.any(corner[:, 0] > corner[:, 1] + 40)  # the room behind, not the drum
