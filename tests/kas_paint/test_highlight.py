"""Selecting writes 1s into the highlight plane only; clearing clears that plane only; the
LUT shows the highlight colour whatever the other seven planes hold (thesis §3.3)."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.kas.paint import planes
from camlab88.apps.kas.paint.ops import OpsFile
from camlab88.apps.kas.paint.program import HIGHLIGHT_RGB, PaintProgram
from tests.kas_paint.helpers import WALK_FILLS, t5688_line, walk


@pytest.mark.claim(
    "§3.3: highlighting writes a 1 into the highlight plane leaving the other seven planes "
    "untouched; clearing that plane removes every highlight with no redraw",
    measured="the T5688's planes before and after select and clear: only plane 7 changes",
    verdict="agrees")
def test_select_and_clear_touch_only_the_highlight_plane() -> None:
    prog = PaintProgram(walk(5), OpsFile(ops=list(WALK_FILLS)))
    line, term = t5688_line()
    line.send(prog.setup())
    data, _ = prog.frame(3)
    line.send(data)
    before = term.planes.copy()
    assert np.count_nonzero(before & 0x7F) > 1000  # the frame is painted: fills, outlines
    line.send(prog.select(3, (1, 2)))
    lit = (term.planes & 0x80) != 0
    assert np.count_nonzero(lit) > 100
    # every highlighted pixel lies on an outline, which a write to all planes would wipe
    assert np.all(before[lit] & 0x60)
    assert np.array_equal(term.planes & 0x7F, before & 0x7F)
    frame = term.frame()
    lit = np.argwhere((term.indices()[::-1] & 0x80) != 0)
    assert all(tuple(frame[y, x]) == HIGHLIGHT_RGB for y, x in lit[:50])
    line.send(prog.clear_selection())
    assert np.array_equal(term.planes, before)


@pytest.mark.claim(
    "§3.3: on the 8-plane T5688, 32 fill colours in five planes, the four-colour outlines in two,"
    " one highlight plane; the lookup table shows the highlight colour wherever its bit is set",
    measured="the lookup table over all 256 pixel values: highlight wins, then outline, then fill",
    verdict="agrees")
def test_lut_highlight_wins_then_outline_then_fill() -> None:
    fills = [(i, i, i) for i in range(32)]
    outs = [(0, 0, 0), (1, 2, 3), (4, 5, 6), (7, 8, 9)]
    lut = planes.lut(fills, outs, (9, 9, 9))
    assert all(lut[i] == (9, 9, 9) for i in range(128, 256))
    assert lut[0x20 | 7] == (1, 2, 3) and lut[0x60] == (7, 8, 9) and lut[17] == (17, 17, 17)
