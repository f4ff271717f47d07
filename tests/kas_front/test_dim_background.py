"""§3.1.1: with the background shown in edit mode, unmoved chains are drawn in "a dim version
of the line's colour" — each pen's own dim LUT entry (11-13, the guide entries, free in edit
mode), reloaded on the terminal; a moved chain returns to its pen at full brightness."""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas.editor import Editor
from camlab88.apps.kas.model import Chain, Drawing
from camlab88.apps.kas.program import EditorFront, parse_timed_script
from camlab88.apps.kas.program import layout as L
from camlab88.apps.kas.program.screen import dim_pens
from camlab88.emulator.sigma import Terminal
from tests.kas_front.helpers import drive


def _drawing(pens: list[int]) -> Drawing:
    return Drawing([Chain.from_points([(-4 + 2 * i, -1), (-3 + 2 * i, 1)], pen)
                    for i, pen in enumerate(pens)])


def _run(pens: list[int], events: str, background: str = "black"):
    front = EditorFront(Editor(_drawing(pens)), background)
    run = drive(front)
    term = run.terminal
    run.run_script(parse_timed_script(events))
    return front, term


def _pixel_entries(term: Terminal) -> set[int]:
    idx = term.indices()  # row 0 = device y 0 (bottom): the field's rows as in layout
    field = idx[L.FIELD_Y0 + 2:L.FIELD_Y1 - 2, L.FIELD_X0 + 2:L.FIELD_X1 - 2]
    return set(np.unique(field).tolist())


def test_each_pen_has_its_own_dim_version_on_the_terminal() -> None:
    front, term = _run([2, 3, 4], "key e\nkey g\nwait")
    dims = dim_pens(front.editor)
    assert sorted(dims.values()) == [11, 12, 13]
    for pen, entry in dims.items():
        want = np.array(L.dim_rgb(front.lut[pen])) * 17
        assert term.lut[entry].tolist() == want.tolist(), pen
    drawn = _pixel_entries(term)
    assert {11, 12, 13} <= drawn and not {2, 3, 4} & drawn  # all dim, none at full colour


def test_dim_is_between_the_background_and_the_pen() -> None:
    red = L.lut_plan()[2]
    assert L.dim_rgb(red) == (7, 0, 0) and L.dim_rgb(red, "white") == (15, 8, 8)
    front, term = _run([2, 3], "key e\nkey g\nwait", background="white")
    entry = dim_pens(front.editor)[2]
    assert term.lut[entry].tolist() == [255, 136, 136]


def test_a_moved_chain_is_bright_and_leaves_the_dim_entries() -> None:
    # move the first chain (pen 2) a little: it is drawn in pen 2 again, the others stay dim
    front, term = _run([2, 3, 4], "key e\nkey g\nkey l\ndown -4 -1\nup -4 -1\ndown -4 -0.5\n"
                       "up -4 -0.5\nwait")
    dims = dim_pens(front.editor)
    assert 2 not in dims and set(dims) == {3, 4}
    drawn = _pixel_entries(term)
    assert 2 in drawn and {dims[3], dims[4]} <= drawn


def test_a_fourth_pen_shares_the_nearest_dim_colour() -> None:
    front, _term = _run([2, 2, 3, 3, 4, 4, 5], "key e\nkey g\nwait")  # yellow: the fewest points
    dims = dim_pens(front.editor)
    assert dims[2] != dims[3] != dims[4] and dims[5] in (dims[2], dims[3])  # yellow ~ red/green


def test_the_guide_entries_come_back_in_drawing_mode() -> None:
    front, term = _run([2, 3, 4], "key e\nkey g\nwait\nkey e\nwait")
    assert front.editor.mode == "draw"
    for entry in (L.GUIDE, L.GUIDE_NEXT, L.DIM):
        assert term.lut[entry].tolist() == (np.array(front.lut[entry]) * 17).tolist()
