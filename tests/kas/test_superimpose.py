"""The superimposer (§3.1.3): offsets, holding first and last frames, self-superimposition."""

from __future__ import annotations

import pytest

from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from camlab88.apps.kas.superimpose import multiple_image, superimpose


def numbered(n: int, y: float, colour: int = 1) -> AnimSequence:
    """Frame i holds one point at (i, y): the x coordinate tells which frame is shown."""
    return AnimSequence([Drawing([Chain.from_points([(i, y)], colour)]) for i in range(n)])


def shown(frame: Drawing) -> list[tuple[float, float]]:
    return [tuple(c.points[0]) for c in frame.chains]


def test_bird_and_flower_example():
    # Flower 40 frames from 0; bird 50 frames starting after 20 frames: 70 frames in all.
    flower, bird = numbered(40, 0), numbered(50, 1)
    s = superimpose([(flower, 0), (bird, 20)])
    assert len(s) == 70
    assert shown(s.frames[0]) == [(0, 0), (0, 1)]     # bird waits on its first frame
    assert shown(s.frames[19]) == [(19, 0), (0, 1)]
    assert shown(s.frames[20]) == [(20, 0), (0, 1)]   # bird starts moving
    assert shown(s.frames[21]) == [(21, 0), (1, 1)]
    assert shown(s.frames[39]) == [(39, 0), (19, 1)]
    assert shown(s.frames[40]) == [(39, 0), (20, 1)]  # flower holds its last frame
    assert shown(s.frames[69]) == [(39, 0), (49, 1)]


def test_any_number_and_order_kept():
    s = superimpose([(numbered(3, 0), 0), (numbered(2, 1), 0), (numbered(4, 2), 1)])
    assert len(s) == 5
    assert shown(s.frames[4]) == [(2, 0), (1, 1), (3, 2)]


def test_self_superimposition_multiple_image():
    s = multiple_image(numbered(5, 0), copies=3, step=1)
    assert len(s) == 7
    assert shown(s.frames[3]) == [(3, 0), (2, 0), (1, 0)]


def test_errors():
    with pytest.raises(ValueError):
        superimpose([])
    with pytest.raises(ValueError, match="offsets"):
        superimpose([(numbered(2, 0), -1)])
    with pytest.raises(ValueError, match="frame rates"):
        superimpose([(numbered(2, 0), 0), (AnimSequence(numbered(2, 0).frames, 24.0), 0)])
