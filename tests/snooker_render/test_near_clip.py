"""§6.4.1: faces are clipped so nothing behind the observer is drawn: a polygon is cut 1 cm
in front of it (ours), and one wholly behind it gives nothing."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.render.frame import clip_project
from camlab88.apps.snooker.render.pinhole import Pinhole


def test_a_face_behind_the_observer_is_not_drawn_and_a_crossing_one_is_cut_at_1_cm() -> None:
    pin = Pinhole.of(np.array([0.0, 0.0, 0.5]), np.array([1.0, 0.0, 0.5]), 50.0, 768, 512)
    behind = np.array([[-1.0, -0.2, 0.0], [-0.5, -0.2, 0.0], [-0.5, 0.2, 0.0], [-1.0, 0.2, 0.0]])
    assert clip_project(pin, behind) is None
    crossing = np.array([[-1.0, -0.2, 0.0], [2.0, -0.2, 0.0], [2.0, 0.2, 0.0], [-1.0, 0.2, 0.0]])
    xy = clip_project(pin, crossing)
    assert xy is not None and len(xy) == 4
    cam = pin.to_camera(np.array([[0.01, 0.0, 0.0]]))  # a point 1 cm ahead, on the cloth
    near_y = pin.project(np.array([[0.01, 0.2, 0.0]]))[0][0, 1]
    assert cam[0, 2] > 0 and np.isclose(xy[:, 1].max(), near_y, rtol=1e-6)
