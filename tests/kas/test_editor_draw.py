"""The editor model in drawing mode, driven by scripted stylus and keyboard events."""

from __future__ import annotations

import math

import numpy as np

from camlab88.apps.kas.editor import MENU_ITEMS, Editor, menu_layout
from camlab88.apps.kas.events import Key, MenuPick, Pointer
from camlab88.apps.kas.model import Chain, Drawing

from .helpers import keys, pts, tap, typed


def menu_touch(item: str) -> list:
    box = next(b for b in menu_layout() if b[0] == item)
    x, y = (box[1] + box[3]) / 2, (box[2] + box[4]) / 2
    return tap(x, y)


def test_freehand_chain_while_stylus_down():
    ed = Editor()
    ed.run([Pointer(0, 0, True), Pointer(0.01, 0, True), Pointer(0.1, 0, True),
            Pointer(0.2, 0.1, True), Pointer(0.2, 0.1, False)])
    assert pts(ed, 0) == [[0, 0], [0.1, 0], [0.2, 0.1]]  # 0.01 is tablet jitter


def test_straight_segments_by_lifting_the_stylus():
    ed = Editor()
    ed.run(tap(0, 0) + [Pointer(3, 3, False)] + tap(1, 0) + tap(1, 1))
    assert len(ed.drawing.chains) == 1
    assert pts(ed, 0) == [[0, 0], [1, 0], [1, 1]]


def test_space_breaks_the_chain():
    ed = Editor()
    ed.run(tap(0, 0) + tap(1, 0) + keys("space") + tap(2, 2) + tap(3, 2))
    assert [pts(ed, i) for i in range(2)] == [[[0, 0], [1, 0]], [[2, 2], [3, 2]]]


def test_rectangle_and_circle():
    ed = Editor()
    ed.run(tap(-1, -1) + keys("r") + tap(0, 0) + tap(2, 1) + keys("c") + tap(0, 0) + tap(1, 0))
    assert pts(ed, 1) == [[0, 0], [2, 0], [2, 1], [0, 1], [0, 0]]
    circ = ed.drawing.chains[2].points
    assert len(circ) == 37 and np.array_equal(circ[0], circ[-1])
    assert np.allclose(np.hypot(*circ.T), 1.0)
    assert not ed.open_chain  # the next touch starts a new chain
    ed.run(tap(5, 0))
    assert len(ed.drawing.chains) == 4


def test_paint_pots_from_menu_and_keys_colour_segments():
    ed = Editor()
    ed.run(menu_touch("pen3") + tap(0, 0) + tap(1, 0) + keys("5") + tap(2, 0))
    assert ed.drawing.chains[0].colours.tolist() == [3, 3, 5]
    assert len(ed.drawing.chains) == 1  # touching the menu drew nothing
    ed.feed(MenuPick("pen7"))
    assert ed.pen == 7


def test_undo_point_chain_section_in_reverse_order():
    ed = Editor()
    ed.run(tap(0, 0) + tap(1, 0) + keys("n", "space") + tap(0, 1) + tap(1, 1) + keys("space")
           + tap(0, 2) + tap(1, 2) + tap(2, 2))
    assert [c.section for c in ed.drawing.chains] == [0, 1, 1]
    ed.feed(Key("U"))  # the thesis's 'U'
    assert pts(ed, 2) == [[0, 2], [1, 2]]
    ed.run(tap(5, 3))  # drawing carries on from the undone point
    assert pts(ed, 2) == [[0, 2], [1, 2], [5, 3]]
    ed.run(keys("k"))
    assert len(ed.drawing.chains) == 2
    ed.run(menu_touch("undo-section"))
    assert len(ed.drawing.chains) == 1 and ed.drawing.chains[0].section == 0
    ed.run(menu_touch("undo") * 1 + keys("u"))
    assert ed.drawing.chains == []
    ed.run(keys("u"))
    assert "nothing" in ed.message


def test_menu_items_all_reachable():
    hits = {b[0] for b in menu_layout()}
    assert hits == set(MENU_ITEMS)


def test_enlarge_view_and_reverse():
    ed = Editor()
    ed.run([Pointer(2, 1, False), Key("v")])
    assert (ed.view.cx, ed.view.cy, ed.view.zoom) == (2, 1, 2)
    ed.run(tap(1, 0))  # screen (1, 0) is world (2.5, 1) when enlarged x2 about (2, 1)
    assert pts(ed, 0) == [[2.5, 1]]
    ed.run(keys("o"))
    assert ed.view.zoom == 1 and ed.view.cx == 0
    ed.run(keys("o"))
    assert "not enlarged" in ed.message


def test_working_area_larger_than_screen():
    ed = Editor()
    ed.run(keys("right", "right", "right", "right") + tap(0, 0))
    assert pts(ed, 0) == [[12, 0]]  # drawn a whole field-width off-screen
    ed.run(keys(*["right"] * 40) + tap(0, 0))
    assert "outside the working area" in ed.message
    assert len(ed.drawing.chains[0]) == 1


def test_guide_highlights_corresponding_chain():
    prev = Drawing([Chain.from_points([(0, 0), (1, 0)]), Chain.from_points([(0, 1), (1, 1)]),
                    Chain.from_points([(0, 2)])])
    ed = Editor(guide=prev)

    def next_guide():
        items = [d for d in ed.display_list() if d.style.startswith("guide")]
        nxt = [i for i, d in enumerate(items) if d.style == "guide-next"]
        return nxt[0] if nxt else None

    assert next_guide() == 0
    ed.run(tap(0, 0))
    assert next_guide() == 0  # still drawing the first chain
    ed.run(tap(1, 0) + keys("space"))
    assert next_guide() == 1
    ed.run(tap(0, 1) + keys("space") + tap(0, 2) + keys("space"))
    assert next_guide() is None  # all drawn
    ed.run(keys("g"))
    assert not [d for d in ed.display_list() if d.style.startswith("guide")]


def test_unknown_key_and_number_prompt_errors():
    ed = Editor()
    ed.run(keys("q"))
    assert "no command" in ed.message
    ed.run(tap(0, 0) + tap(1, 0) + keys("e", "t") + tap(0, 0) + typed("abc"))
    # letters are not digits: the prompt refuses the empty number and still waits
    assert ed.pending is not None and "not a number" in ed.message
    ed.run(typed("1e9x"))  # 'e' and 'x' ignored -> "19"
    assert ed.pending is None and np.allclose(pts(ed, 0)[1], [math.cos(math.radians(19)),
                                                              math.sin(math.radians(19))])
    ed.run(keys("t") + tap(0, 0))
    ed.run(keys("escape"))
    assert ed.pending is None


def test_circle_uses_rim_for_radius():
    ed = Editor()
    ed.run(keys("c") + tap(1, 1) + tap(1, 3))
    r = np.hypot(*(ed.drawing.chains[0].points - (1, 1)).T)
    assert np.allclose(r, 2) and math.isclose(ed.drawing.chains[0].points[0, 1], 3)


def test_unknown_menu_item_is_a_message_not_a_crash():
    ed = Editor()
    ed.feed(MenuPick("launch"))
    assert "no menu item" in ed.message


def test_failed_save_is_shown_and_quit_warns_while_dirty():
    from camlab88.apps.kas.editor import Editor
    from camlab88.apps.kas.events import Key, Pointer

    ed = Editor()
    ed.run([Pointer(0, 0, True), Pointer(0, 0, False), Pointer(1, 1, True),
            Pointer(1, 1, False)])

    def full(_d):
        raise OSError(28, "No space left on device")

    ed.on_save = full
    ed.feed(Key("f2"))
    assert "NOT saved" in ed.message and "No space" in ed.message
    assert ed.dirty and ed.drawing.n_points == 2
    assert not ed.request_quit() and "unsaved" in ed.message
    assert ed.request_quit()          # closing again straight away discards
    ed.feed(Pointer(2, 2, True))
    assert not ed.request_quit()      # an event in between: warn again
    saved = []
    ed.on_save = saved.append
    ed.feed(Key("f2"))
    assert saved and not ed.dirty and ed.request_quit()
