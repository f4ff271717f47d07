"""Ball centres land on the pixels the camera issue's projection (and so the visualiser)
puts them on; the pinhole's rays invert it."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.snooker.camera.projection import project
from camlab88.apps.snooker.render.frame import frame_geometry
from camlab88.apps.snooker.render.painter import BallItem
from camlab88.apps.snooker.render.pinhole import Pinhole
from camlab88.apps.snooker.render.shading import lights_array
from camlab88.apps.snooker.render.truecolour import draw_ball
from camlab88.apps.snooker.visualiser.scene import ball_discs
from tests.snooker_render.helpers import break_scene, break_views

W, H = 768, 512


def test_rays_run_back_through_the_projected_points() -> None:
    v = break_views()[10]
    pin = Pinhole.of(np.array(v.observer), np.array(v.viewpoint), v.focal_mm, W, H)
    pts = np.random.default_rng(1).uniform(-1.5, 1.5, size=(50, 3)) * (1, 0.6, 0.1)
    xy, depth, vis = pin.project(pts)
    d = pin.rays(xy[:, 0], xy[:, 1])
    along = pin.observer + d * depth[:, None]  # rays have unit forward component
    assert vis.all()
    assert np.allclose(along, pts, atol=1e-9)


def _coverage_centroids(scene, view):
    """Each ball's coverage map (drawn over black and over white: cov = 1 - (w - b)) and
    its coverage-weighted centroid in screen pixels."""
    g = frame_geometry(scene, np.array(view.observer), np.array(view.viewpoint),
                       view.focal_mm, view.frame, W, H)
    lights = lights_array(scene.lights)
    out = {}
    for item in g.items:
        if not isinstance(item, BallItem):
            continue
        black, white = np.zeros((H, W, 3)), np.ones((H, W, 3))
        draw_ball(black, scene, g, item, lights, True)
        draw_ball(white, scene, g, item, lights, True)
        cov = 1.0 - (white - black)[..., 0]
        ys, xs = np.nonzero(cov > 1e-12)
        w = cov[ys, xs]
        out[item.ball] = (np.sum((xs + 0.5) * w) / w.sum(), np.sum((ys + 0.5) * w) / w.sum())
    return out


@pytest.mark.claim(
    "§6.4: the rendered view should agree exactly with the view predicted at the camera "
    "definition stage",
    measured="rendered ball centres against the visualiser's projection",
    verdict="agrees")
def test_ball_centres_land_where_the_visualiser_puts_them() -> None:
    scene = break_scene()
    for view in (break_views()[0], break_views()[25]):
        cam = view.camera()
        row = scene.index(view.frame)
        xy, _depth, _vis = project(cam, scene.centres[row], W, H)
        discs = {}
        for cx, cy, _r, _value in ball_discs(cam, scene.centres[row], scene.on_table[row],
                                             scene.table.radius, W, H):
            discs.setdefault((cx, cy), True)
        got = _coverage_centroids(scene, view)
        checked = 0
        for b, (gx, gy) in got.items():
            x, y = xy[b]
            if not (20 < x < W - 20 and 20 < y < H - 20):
                continue  # a clipped disc's centroid is not its centre
            assert abs(gx - x) < 0.02 and abs(gy - y) < 0.02, (b, gx, gy, x, y)
            assert (int(np.floor(x)), int(np.floor(y))) in discs  # the visualiser's pixel
            assert (np.floor(gx), np.floor(gy)) == (np.floor(x), np.floor(y))
            checked += 1
        assert checked >= 10
