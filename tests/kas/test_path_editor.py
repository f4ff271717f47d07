"""Drawing a sample path and tick marks with scripted events (§3.1.2)."""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas.events import Pointer
from camlab88.apps.kas.inbetween import inbetween
from camlab88.apps.kas.model import Chain, Drawing
from camlab88.apps.kas.path_editor import PathEditor

from .helpers import keys, tap


def editor() -> PathEditor:
    a = Drawing([Chain.from_points([(0, 0), (1, 0)])])
    b = Drawing([Chain.from_points([(4, 0), (5, 0)])])
    return PathEditor(a, b)


def test_draw_path_then_ticks():
    pe = editor()
    pe.run([Pointer(0, 0, True), Pointer(1, 0, True), Pointer(2, 0, True), Pointer(4, 0, True),
            Pointer(4, 0, False)])
    assert pe.path == [(0, 0), (1, 0), (2, 0), (4, 0)]
    pe.run(keys("t") + tap(1, 0.3) + tap(2, -1) + tap(3, 0))
    assert pe.ticks == [0.25, 0.5, 0.75]
    assert np.allclose(pe.tick_points(), [[1, 0], [2, 0], [3, 0]])
    seq = inbetween(pe.first, pe.second, path=pe.sample_path(), timing=pe.timing())
    assert [f.chains[0].points[0, 0] for f in seq.frames] == [0, 1, 2, 3, 4]
    pe.run(keys("u"))
    assert pe.ticks == [0.25, 0.5]
    roles = {r for r, _, _ in pe.display_list()}
    assert roles == {"first", "second", "path", "tick"}


def test_ticks_touched_out_of_order_follow_the_path():
    # the reviewer's script: ticks touched at 3/4, 1/4, 1/2 of the path
    pe = editor()
    pe.run([Pointer(0, 0, True), Pointer(4, 0, True), Pointer(4, 0, False)])
    pe.run(keys("t") + tap(3, 0) + tap(1, 0) + tap(2, 0))
    assert pe.timing().values.tolist() == [0.25, 0.5, 0.75]
    seq = inbetween(pe.first, pe.second, path=pe.sample_path(), timing=pe.timing())
    assert [f.chains[0].points[0, 0] for f in seq.frames] == [0, 1, 2, 3, 4]


def test_path_needs_one_stroke_and_can_be_cleared():
    pe = editor()
    pe.run(keys("t"))
    assert "draw the path first" in pe.message and pe.mode == "path"
    pe.run(tap(0, 0) + tap(1, 1))
    assert pe.path == [(0, 0)] and "one stroke" in pe.message
    pe.run(keys("c"))
    assert pe.path == [] and pe.ticks == []
