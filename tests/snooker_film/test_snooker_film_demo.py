"""The demo act's frames: a break from the motion program, through a camera script, to
rendered frames — deterministic, and the balls move."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.film.demo import film_frames


def test_the_demo_act_films_a_break() -> None:
    a = list(film_frames(12, (96, 64)))
    assert len(a) == 12 and a[0].shape == (64, 96, 3) and a[0].dtype == np.uint8
    assert not np.array_equal(a[0], a[-1])
    assert all(np.array_equal(x, y) for x, y in zip(a, film_frames(12, (96, 64)), strict=True))
