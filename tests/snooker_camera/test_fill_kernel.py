"""The visualiser's convex-polygon kernel fills exactly the pixels the plain numpy rule
fills (pixel centres inside, even-odd over the polygon's edges), for random convex polygons
partly or wholly off the picture, and degenerate ones."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.snooker.visualiser.spans import fill_convex

H, W = 60, 80


def reference(xy: np.ndarray) -> np.ndarray:
    """Pixel (x, y) is inside when its centre's row crosses the polygon between the
    leftmost and rightmost edge crossings (left edge in, right edge out)."""
    img = np.zeros((H, W), dtype=np.uint8)
    a, b = xy, np.roll(xy, -1, axis=0)
    for y in range(H):
        cy = y + 0.5
        xs = [a[i, 0] + (cy - a[i, 1]) * (b[i, 0] - a[i, 0]) / (b[i, 1] - a[i, 1])
              for i in range(len(xy)) if (a[i, 1] <= cy) != (b[i, 1] <= cy)]
        if xs:
            cx = np.arange(W) + 0.5
            img[y, (cx >= min(xs)) & (cx < max(xs))] = 7
    return img


def convex(cx: float, cy: float, r: float, angles: list[float]) -> np.ndarray:
    t = np.sort(np.array(angles))
    return np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)])


@settings(max_examples=150, deadline=None)
@given(st.floats(-40, 120), st.floats(-30, 90), st.floats(0.1, 70),
       st.lists(st.floats(0, 2 * np.pi), min_size=3, max_size=9, unique=True))
def test_kernel_matches_reference(cx: float, cy: float, r: float, angles: list[float]) -> None:
    xy = convex(cx, cy, r, angles)
    img = np.zeros((H, W), dtype=np.uint8)
    fill_convex(img, xy, 7)
    assert np.array_equal(img, reference(xy))


def test_a_polygon_covering_the_picture_fills_all_and_a_sliver_nothing() -> None:
    img = np.zeros((H, W), dtype=np.uint8)
    big = np.array([[-10.0, -10.0], [200.0, -10.0], [200.0, 200.0], [-10.0, 200.0]])
    fill_convex(img, big, 3)
    assert np.all(img == 3)
    img[:] = 0
    fill_convex(img, np.array([[10.0, 10.2], [50.0, 10.2], [50.0, 10.4]]), 3)
    assert not img.any()  # between two pixel-centre rows
