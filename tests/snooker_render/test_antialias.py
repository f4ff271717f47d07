"""Coverage anti-aliasing against exact areas (thesis 6.4.1): a ball's disc, and a
polygon's edges by Pitteway & Watkinson's area rule."""

from __future__ import annotations

import numpy as np

from apps.snooker.render import kernels as K

SUB = 64  # supersamples per pixel side for the exact reference


def _exact(inside, h: int, w: int) -> np.ndarray:  # noqa: ANN001
    s = (np.arange(SUB) + 0.5) / SUB
    ys = (np.arange(h)[:, None, None, None] + s[None, None, :, None])
    xs = (np.arange(w)[None, :, None, None] + s[None, None, None, :])
    ys, xs = np.broadcast_arrays(ys, xs)
    return inside(xs, ys).mean(axis=(2, 3))


def _disc_coverage(cx: float, cy: float, r: float, size: int) -> np.ndarray:
    """The ball kernel's coverage: draw a white ball over black and over white."""
    from apps.snooker.render.balls import ball_params
    from apps.snooker.render.lights import Lights

    dark = Lights(np.zeros((1, 3)) + 5.0, np.zeros((1, 3)), np.full(3, 1.0))
    b = ball_params(np.array([cx, cy]), r, np.zeros(3), 0.02, np.ones(3), np.eye(3), dark,
                    False)
    cam = np.zeros(15)
    cam[0:3] = (0.0, 0.0, 1.0)
    cam[3:6], cam[6:9], cam[9:12] = (1, 0, 0), (0, 1, 0), (0, 0, -1)
    black, white = np.zeros((size, size, 3)), np.ones((size, size, 3))
    lights = np.array([[5.0, 5.0, 5.0, 0.0, 0.0, 0.0]])
    K.ball(black, cam, b, lights, np.zeros((1, 3)))
    K.ball(white, cam, b, lights, np.zeros((1, 3)))
    return 1.0 - (white - black)[..., 0]


def test_disc_coverage_against_the_analytic_disc() -> None:
    rng = np.random.default_rng(7)
    for r in (2.3, 4.0, 9.7):
        cx, cy = 16 + rng.random(2)
        got = _disc_coverage(cx, cy, r, 32)
        want = _exact(lambda x, y, cx=cx, cy=cy, r=r: (x - cx) ** 2 + (y - cy) ** 2 <= r * r,
                      32, 32)
        err = np.abs(got - want)
        assert err.max() < 0.09, (r, err.max())
        edge = (want > 0) & (want < 1)
        assert err[edge].mean() < 0.03
        assert abs(got.sum() - np.pi * r * r) < 0.005 * np.pi * r * r + 0.1


def test_polygon_edges_against_exact_areas() -> None:
    verts = np.array([[3.2, 4.7], [40.6, 9.1], [35.3, 37.8], [8.9, 30.2]])
    img = np.zeros((44, 44, 1))
    K.polygon(img, verts, np.ones(1))

    def inside(x, y):  # noqa: ANN001, ANN202
        ok = np.ones_like(x, dtype=bool)
        for k in range(4):
            (ax, ay), (bx, by) = verts[k], verts[(k + 1) % 4]
            ok &= (bx - ax) * (y - ay) - (by - ay) * (x - ax) >= 0
        return ok

    want = _exact(inside, 44, 44)
    err = np.abs(img[..., 0] - want)
    edge = (want > 0) & (want < 1)
    corners = np.zeros_like(edge)
    for vx, vy in verts:
        corners[int(vy) - 1:int(vy) + 2, int(vx) - 1:int(vx) + 2] = True
    # the area rule is exact where an edge crosses a pixel's two sides; where it cuts a
    # corner instead it errs by at most m / 8 (m = the edge's minor / major slope)
    d = np.diff(np.vstack([verts, verts[:1]]), axis=0)
    m = np.max(np.min(np.abs(d), axis=1) / np.max(np.abs(d), axis=1))
    assert err[edge & ~corners].max() <= m / 8 + 1e-3
    assert err[edge & ~corners].mean() < 0.01
    assert err.max() < 0.2
    assert abs(img.sum() - want.sum()) < 0.5


def test_pw_coverage_of_a_pixel_on_a_shallow_edge_is_the_height_at_its_centre() -> None:
    # edge y = 10.3 + 0.25 (x - 0): the pixel column x in [4, 5) has centre 4.5, line height
    # there 11.425, so the pixel row 11 ([11, 12)) is covered 0.425 below the line
    verts = np.array([[0.0, 10.3], [0.0, 30.0], [40.0, 30.0], [40.0, 20.3]])
    orient = 1.0 if np.sum(verts[:, 0] * np.roll(verts[:, 1], -1)
                           - np.roll(verts[:, 0], -1) * verts[:, 1]) > 0 else -1.0
    assert np.isclose(K.coverage_at(verts, orient, 4.5, 11.5), 1 - 0.425)
