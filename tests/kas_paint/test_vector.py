"""The host's copy of the firmware vector sets exactly the pixels the terminal sets."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.kas.paint import vector
from camlab88.emulator.sigma import raster

coord = st.integers(0, 700)


@settings(max_examples=200, deadline=None)
@given(coord, coord, coord, coord)
def test_segment_matches_firmware(x0: int, y0: int, x1: int, y1: int) -> None:
    x, y, _ = vector.polyline_pixels(np.array([[x0, y0], [x1, y1]]))
    assert sorted(set(zip(x.tolist(), y.tolist()))) == raster.firmware_line_points(x0, y0,
                                                                                    x1, y1)


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 120), st.integers(0, 90)), min_size=1, max_size=12))
def test_polyline_matches_terminal_planes(pts: list[tuple[int, int]]) -> None:
    p = np.array(pts, dtype=np.int64)
    mine = np.zeros((100, 130), dtype=np.uint8)
    vector.stamp(mine, p)
    theirs = np.zeros((100, 130), dtype=np.uint8)
    xy = np.ascontiguousarray(p[1:] if len(p) > 1 else p, dtype=np.int32)  # as the decoder
    raster.draw_polyline(theirs, xy, int(p[0, 0]), int(p[0, 1]), 1,
                         0xFF, 0, 0, 0, False)
    assert np.array_equal(mine, theirs)
