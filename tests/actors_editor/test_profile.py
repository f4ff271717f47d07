"""The profile being drawn: snapping, the order of points (heights never decrease, as the
actors file requires), hits, dragging within the neighbours' heights, deleting."""

from __future__ import annotations

from camlab88.apps.actors.editor.layout import MAX_HEIGHT, MAX_RADIUS
from camlab88.apps.actors.editor.profile import Profile, to_pixels, to_units


def _pad(r: float, h: float) -> tuple[int, int]:
    return to_pixels((r, h))


def test_pixels_snap_to_an_eightieth_of_a_cell_and_stay_in_the_pad() -> None:
    assert to_units(*_pad(0.25, 0.5)) == (0.25, 0.5)
    assert to_units(16 + 81, 432 - 1) == (0.25, 0.0)  # 81 px: nearest 4-pixel step
    assert to_units(-50, 900) == (0.0, 0.0)
    r, h = to_units(10_000, -10_000)
    assert MAX_RADIUS - 0.0125 < r <= MAX_RADIUS and MAX_HEIGHT - 0.0125 < h <= MAX_HEIGHT


def test_new_points_keep_heights_in_order() -> None:
    p = Profile()
    for r, h in [(0.3, 0.0), (0.1, 0.5), (0.2, 0.25), (0.0, 0.5), (0.0, 0.0)]:
        p.add(*_pad(r, h))
    assert p.points == [(0.3, 0.0), (0.0, 0.0), (0.2, 0.25), (0.1, 0.5), (0.0, 0.5)]


def test_a_dragged_point_stays_between_its_neighbours_heights() -> None:
    p = Profile(((0.3, 0.0), (0.2, 0.25), (0.1, 0.5)))
    assert p.move(1, *_pad(0.25, 0.9))
    assert p.points[1] == (0.25, 0.5)
    assert p.move(1, *_pad(0.05, -1))
    assert p.points[1] == (0.05, 0.0)
    assert not p.move(1, *_pad(0.05, 0.0))


def test_hit_finds_the_point_under_the_cursor_and_delete_removes_it() -> None:
    p = Profile(((0.3, 0.0), (0.2, 0.25)))
    x, y = _pad(0.2, 0.25)
    assert p.hit(x + 4, y - 3) == 1
    assert p.hit(x + 20, y) is None
    p.delete(1)
    assert p.points == [(0.3, 0.0)]
