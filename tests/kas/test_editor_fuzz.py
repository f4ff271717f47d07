"""Random event streams never crash the editor and keep its data consistent."""

from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from camlab88.apps.kas.editor import MENU_ITEMS, Editor
from camlab88.apps.kas.events import Key, MenuPick, Pointer

coord = st.floats(-7, 6, allow_nan=False).map(lambda v: round(v, 2))
pointer = st.builds(Pointer, coord, coord, st.booleans())
key = st.sampled_from(list("0123456789.-,[]abcdefghijklmnopqrstuvwxyz")
                      + ["space", "return", "backspace", "escape", "tab", "up", "down",
                         "left", "right", "f2"]).map(Key)
menu = st.sampled_from(MENU_ITEMS).map(MenuPick)
events = st.lists(st.one_of(pointer, pointer, pointer, key, key, menu), max_size=120)


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(events, st.integers(0, 3))
def test_random_sessions_keep_the_drawing_consistent(evs, seed):
    ed = Editor(seed=seed)
    for ev in evs:
        ed.feed(ev)
        for c in ed.drawing.chains:
            assert len(c) >= 1 and c.points.shape == (len(c), 2) and len(c.colours) == len(c)
            assert np.isfinite(c.points).all()
            assert np.abs(c.points).max() <= 48.0
        if ed.mode == "edit" and ed.drawing.chains:
            for ci, pi in (ed.square, ed.triangle):
                assert 0 <= ci < len(ed.drawing.chains)
                assert 0 <= pi < len(ed.drawing.chains[ci])
    ed.display_list()
    ed.cursors()
