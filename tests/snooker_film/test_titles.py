"""Title animation (thesis 6.5): giant lettered balls, aimed with the motion program's own
"set up next shot" tool, stop together on their slots and spell the word; the table is
invisible; the letters face the camera when the word forms."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.snooker.film.letterballs import INK, render_title
from camlab88.apps.snooker.film.titles import WORD, slots, title_scene, title_session
from camlab88.apps.snooker.render.gamma import encode


@pytest.fixture(scope="module")
def title() -> tuple:
    return title_scene()


def test_the_aimed_balls_stop_together_on_their_slots(title: tuple) -> None:
    s = title_session()
    assert np.all(np.hypot(*s.balls.vel[: len(WORD)].T) > 0)  # each struck by its aim
    scene, _view = title
    moving = np.any(np.diff(scene.centres[:, : len(WORD)], axis=0) != 0, axis=2)
    last_move = [int(np.flatnonzero(moving[:, b])[-1]) for b in range(len(WORD))]
    assert max(last_move) - min(last_move) <= 1  # the word forms at one moment
    end = scene.centres[-1, : len(WORD), :2]
    shift = np.array([scene.table.length_m, scene.table.width_m]) / 2
    assert np.allclose(end, np.array(slots(scene.table, WORD)) - shift, atol=1e-3)
    assert not scene.on_table[:, len(WORD):].any()  # no other balls


@pytest.mark.claim(
    "§6.5: for titles the table becomes invisible and the larger balls carry letters that line up"
    " into words",
    measured="the rendered title frame: the word's letters on the balls, no table pixels",
    verdict="agrees")
def test_the_word_is_spelt_and_the_table_is_invisible(title: tuple) -> None:
    scene, view = title
    img = render_title(scene, view, scene.n_frames, 384, 192)
    xy, _, _ = _project(scene, view, 384, 192)
    ink = encode(INK)
    near_ink = np.abs(img.astype(int) - ink).sum(axis=2) < 60
    r = 12
    for b in range(len(WORD)):
        x, y = (int(round(v)) for v in xy[b])
        assert near_ink[y - r:y + r, x - r:x + r].sum() > 10, WORD[b]
    far = np.ones(img.shape[:2], dtype=bool)
    for x, y in xy[: len(WORD)]:
        far[max(int(y) - 30, 0):int(y) + 30, max(int(x) - 30, 0):int(x) + 30] = False
    assert not img[far].any()  # no table, no surround: black away from the balls
    first = render_title(scene, view, 1, 384, 192)
    assert not np.array_equal(first, img)


def _project(scene, view, w, h):
    from camlab88.apps.snooker.render.pinhole import Pinhole

    pin = Pinhole.of(np.asarray(view.observer), np.asarray(view.viewpoint), view.focal_mm,
                     w, h)
    return pin.project(scene.centres[-1])
