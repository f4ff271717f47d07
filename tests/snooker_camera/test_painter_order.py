"""The visualiser's table boxes are drawn in a painter's order that is right, checked by
rays instead of by the separating planes the order is made from (docs/fidelity/snooker.md:
"The table as boxes ... painter's order by separating planes")."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.snooker.table import Table
from camlab88.apps.snooker.visualiser import table_model as tm

OBSERVERS = [(-2.2, 0.0, 0.6), (2.0, 1.3, 0.25), (0.0, -1.4, 0.05), (1.0, 0.3, 2.5),
             (-1.6, -1.2, 0.15), (0.0, 0.0, -0.5)]


def _entry(box: tm.Box, o: np.ndarray, d: np.ndarray) -> float | None:
    """Where a ray o + t·d (t > 0) enters the box (slab method), or None if it misses."""
    lo, hi = np.array(box.lo), np.array(box.hi)
    with np.errstate(divide="ignore", invalid="ignore"):
        t1, t2 = (lo - o) / d, (hi - o) / d
    near = np.nanmax(np.minimum(t1, t2))
    far = np.nanmin(np.maximum(t1, t2))
    return float(near) if near < far - 1e-9 and far > 0 else None


@pytest.mark.parametrize("observer", OBSERVERS)
def test_nearer_box_on_any_ray_is_drawn_later(observer: tuple[float, float, float]) -> None:
    o = np.array(observer)
    boxes = tm.boxes(Table())
    order = {id(b): i for i, b in enumerate(tm.painter_order(boxes, o))}
    rng = np.random.default_rng(6)
    hits = 0
    for box in boxes:  # rays from the observer to points inside every box
        lo, hi = np.array(box.lo), np.array(box.hi)
        for p in lo + rng.random((60, 3)) * (hi - lo):
            d = p - o
            seen = sorted((t, order[id(b)]) for b in boxes if (t := _entry(b, o, d)) is not None)
            for (t_near, near), (t_far, far) in zip(seen, seen[1:]):
                if t_far - t_near > 1e-9:  # not entered at the same point
                    hits += 1
                    assert near > far, f"observer {observer}: a nearer box drawn before a " \
                                       "farther one on the same ray"
    assert hits > 50  # the rays did cross boxes in depth
