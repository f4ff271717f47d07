"""The editor model in edit mode: every command, move back / again, background display."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.kas.editor import Editor
from camlab88.apps.kas.events import Key, MenuPick
from camlab88.apps.kas.model import Chain, Drawing

from .helpers import keys, pts, tap, typed


def start() -> Editor:
    d = Drawing([Chain.from_points([(0, 0), (1, 0), (2, 0)], 1, 0),
                 Chain.from_points([(0, 1), (1, 1)], 2, 1),
                 Chain.from_points([(0, 2), (1, 2), (2, 2)], 3, 1)])
    ed = Editor(d)
    ed.feed(MenuPick("edit"))
    return ed


def select(ed: Editor, square: int, triangle: int) -> None:
    ed.set_cursor("square", square)
    ed.set_cursor("triangle", triangle)


def all_pts(ed: Editor) -> list:
    return [pts(ed, i) for i in range(len(ed.drawing.chains))]


ORIGINAL = [[[0, 0], [1, 0], [2, 0]], [[0, 1], [1, 1]], [[0, 2], [1, 2], [2, 2]]]


def test_cursors_move_along_chains_in_drawing_order():
    ed = start()
    assert ed.mode == "edit" and ed.square == (0, 0) and ed.triangle == (2, 2)
    ed.run(keys(".", ".", ".", "."))
    assert ed.square == (1, 1)  # crossed from chain 0 into chain 1
    ed.run(keys("tab", ","))
    assert ed.triangle == (2, 1)
    ed.run(keys("[", "["))
    assert ed.triangle == (0, 0)
    ed.run(keys("tab") + tap(1.9, 2.1))  # the stylus snaps the square to the nearest point
    assert ed.square == (2, 2)
    assert ed.selection() == [(0, 0, 2), (1, 0, 1), (2, 0, 2)]
    select(ed, 2, 4)
    assert ed.selection() == [(0, 2, 2), (1, 0, 1)]


def test_move_points_only_between_cursors():
    ed = start()
    select(ed, 1, 3)  # (1,0), (2,0) and (0,1)
    ed.run(keys("m") + tap(0, 0) + tap(0.5, 0.25))
    assert all_pts(ed)[:2] == [[[0, 0], [1.5, 0.25], [2.5, 0.25]], [[0.5, 1.25], [1, 1]]]


def test_move_chain_and_section():
    ed = start()
    select(ed, 3, 3)  # square on chain 1
    ed.run(keys("l") + tap(0, 0) + tap(1, 0))
    assert pts(ed, 1) == [[1, 1], [2, 1]] and pts(ed, 2) == ORIGINAL[2]
    ed.run(keys("s") + tap(0, 0) + tap(0, -1))  # section 1 = chains 1 and 2
    assert pts(ed, 1) == [[1, 0], [2, 0]] and pts(ed, 2) == [[0, 1], [1, 1], [2, 1]]
    assert pts(ed, 0) == ORIGINAL[0]


def test_rotate_about_origin():
    ed = start()
    select(ed, 0, 2)
    ed.run(keys("t") + tap(1, 0) + typed("90"))
    assert np.allclose(ed.drawing.chains[0].points, [[1, -1], [1, 0], [1, 1]])


def test_reflect_in_mirror_line():
    ed = start()
    select(ed, 0, 2)
    ed.run(keys("f") + tap(0, -1) + tap(1, 0))  # the line y = x - 1
    assert np.allclose(ed.drawing.chains[0].points, [[1, -1], [1, 0], [1, 1]])


def test_collapse_onto_point_and_line():
    ed = start()
    select(ed, 0, 2)
    ed.run(keys("p") + tap(3, 3))
    assert pts(ed, 0) == [[3, 3]] * 3
    select(ed, 5, 7)
    ed.run(keys("j") + tap(0, 0) + tap(1, 1))  # project chain 2 onto y = x
    assert np.allclose(ed.drawing.chains[2].points, [[1, 1], [1.5, 1.5], [2, 2]])


def test_delete_points():
    ed = start()
    select(ed, 2, 3)  # end of chain 0 and start of chain 1
    ed.run(keys("d"))
    assert all_pts(ed)[:2] == [[[0, 0], [1, 0]], [[1, 1]]]
    select(ed, 2, 2)
    ed.run(keys("d"))  # chain 1's last point: the chain goes
    assert len(ed.drawing.chains) == 2


def test_insert_points_after_square_cursor():
    ed = start()
    select(ed, 0, 8)
    ed.run(keys("3", "i") + tap(0.5, 0.5) + tap(0.7, 0.5) + keys("space"))
    assert pts(ed, 0) == [[0, 0], [0.5, 0.5], [0.7, 0.5], [1, 0], [2, 0]]
    assert ed.drawing.chains[0].colours.tolist() == [1, 3, 3, 1, 1]
    assert ed.square == (0, 2) and ed.pending is None


def test_enlarge_and_stretch():
    ed = start()
    select(ed, 0, 2)
    ed.run(keys("z") + tap(1, 0) + typed("2"))
    assert pts(ed, 0) == [[-1, 0], [1, 0], [3, 0]]
    select(ed, 5, 7)
    ed.run(keys("y") + tap(0, 2) + typed("3") + typed("0.5"))
    assert pts(ed, 2) == [[0, 2], [3, 2], [6, 2]]
    select(ed, 3, 4)
    ed.run(keys("y") + tap(0, 0) + typed("1") + typed("-1"))  # negative = reflect in x axis
    assert pts(ed, 1) == [[0, -1], [1, -1]]


def test_change_colour_of_segment_and_chain():
    ed = start()
    select(ed, 1, 1)
    ed.run(keys("6", "k"))
    assert ed.drawing.chains[0].colours.tolist() == [1, 1, 6]  # segment (1,0)-(2,0)
    ed.run(keys("7", "h"))
    assert ed.drawing.chains[0].colours.tolist() == [7, 7, 7]


def test_deregularise_fractal_polyline_repeatable():
    runs = []
    for _ in range(2):
        ed = start()
        select(ed, 0, 2)
        ed.run(keys("x") + typed("0.1"))
        runs.append(ed.drawing.chains[0].points.copy())
        c = ed.drawing.chains[0].points
        assert len(c) == 5
        assert np.allclose(c[[0, 2, 4]], ORIGINAL[0])
        assert np.allclose(c[[1, 3], 0], [0.5, 1.5])      # midpoints moved only across the line
        assert np.all(np.abs(c[[1, 3], 1]) <= 0.1) and np.any(c[[1, 3], 1] != 0)
        ed.run(keys("x", "return"))  # again, with the remembered perturbation
        assert len(ed.drawing.chains[0]) == 9
        assert ed.square == (0, 0) and ed.triangle == (0, 8)
    assert np.array_equal(runs[0], runs[1])  # same seed, same wiggles
    other = Editor(Drawing([Chain.from_points(ORIGINAL[0])]), seed=7)
    other.run(keys("e", "x") + typed("0.1"))
    assert not np.array_equal(other.drawing.chains[0].points, runs[0])


def test_move_back_and_again():
    ed = start()
    select(ed, 0, 2)
    ed.run(keys("t") + tap(0, 0) + typed("90"))
    ed.run(keys("b"))
    assert np.allclose(ed.drawing.chains[0].points, ORIGINAL[0])
    ed.run(keys("a"))
    assert np.allclose(ed.drawing.chains[0].points, [[0, 0], [0, 1], [0, 2]])
    select(ed, 5, 7)  # the same rotation again, on another chain
    ed.run(keys("a"))
    assert np.allclose(ed.drawing.chains[2].points, [[-2, 0], [-2, 1], [-2, 2]])
    ed.run(keys("b"))
    assert np.allclose(ed.drawing.chains[2].points, ORIGINAL[2])


def test_move_back_unwinds_a_composite():
    ed = start()
    select(ed, 0, 2)
    # enlarge x2 about (0,0), then move by (0,1), then reflect in the x axis
    ed.run(keys("z") + tap(0, 0) + typed("2"))
    ed.run(keys("m") + tap(0, 0) + tap(0, 1))
    ed.run(keys("f") + tap(0, 0) + tap(1, 0))
    assert np.allclose(ed.drawing.chains[0].points, [[0, -1], [2, -1], [4, -1]])
    ed.run(keys("b", "b", "b"))
    assert np.allclose(ed.drawing.chains[0].points, ORIGINAL[0])
    ed.run(keys("b"))
    assert "every transformation applied" in ed.message
    assert np.allclose(ed.drawing.chains[0].points, ORIGINAL[0])


def _enlarged_twice_then_turned_twice(about: tuple[float, float], degrees: str) -> Editor:
    """The first chain selected: enlarged x2 about (1, 0), again; turned ``degrees`` about
    ``about``, again - four transformations applied."""
    ed = start()
    select(ed, 0, 2)
    ed.run(keys("z") + tap(1, 0) + typed("2") + keys("a"))
    ed.run(keys("t") + tap(*about) + typed(degrees) + keys("a"))
    return ed


def test_move_back_unwinds_repeats_too():
    # four transformations applied, so four move backs undo them, rotations first - never
    # the inverse of something not applied.
    ed = _enlarged_twice_then_turned_twice((0, 0), "90")
    ed.run(keys("b", "b"))  # both rotations undone: back to the twice-enlarged chain
    assert np.allclose(ed.drawing.chains[0].points, [[-3, 0], [1, 0], [5, 0]])
    ed.run(keys("b", "b"))
    assert np.allclose(ed.drawing.chains[0].points, ORIGINAL[0])
    ed.run(keys("b"))
    assert np.allclose(ed.drawing.chains[0].points, ORIGINAL[0])


def test_composite_replayed_elsewhere_with_the_remembered_parameters():
    from camlab88.apps.kas import editor_commands as ops

    ed = _enlarged_twice_then_turned_twice((0, 3), "30")
    ed.run(keys("m") + tap(0, 0) + tap(0.5, -0.25))
    # now on the third chain: Return at every prompt takes the remembered origin, factor,
    # angle and (from a new starting touch) the same move vector
    select(ed, 5, 7)
    ed.run(keys("z", "return", "return", "a"))
    ed.run(keys("t", "return", "return", "a"))
    ed.run(keys("m") + tap(1, 1) + keys("return"))
    m = (ops.translation(0.5, -0.25) @ ops.rotation(30, (0, 3)) @ ops.rotation(30, (0, 3))
         @ ops.scaling(2, 2, (1, 0)) @ ops.scaling(2, 2, (1, 0)))
    want = ops.apply(m, np.array(ORIGINAL[2], float))
    assert np.allclose(ed.drawing.chains[2].points, want)
    assert np.allclose(ed.drawing.chains[0].points, ops.apply(m, np.array(ORIGINAL[0], float)))
    assert np.allclose(ed.drawing.chains[1].points, ORIGINAL[1])


def test_return_at_a_point_prompt_without_memory_waits_for_a_touch():
    ed = start()
    select(ed, 0, 2)
    ed.run(keys("f", "return"))
    assert ed.pending is not None and "touch a point" in ed.message
    ed.run(tap(0, 0) + tap(1, 0))
    assert np.allclose(ed.drawing.chains[0].points, ORIGINAL[0])  # mirror on the chain
    select(ed, 5, 7)
    ed.run(keys("f"))
    assert "as last time" in ed.message
    ed.run(keys("return", "return"))
    assert np.allclose(ed.drawing.chains[2].points, [[0, -2], [1, -2], [2, -2]])


def test_move_again_repeats_move_chain_scope():
    ed = start()
    select(ed, 0, 0)
    ed.run(keys("l") + tap(0, 0) + tap(0, 4))
    select(ed, 3, 3)
    ed.run(keys("a"))
    assert pts(ed, 1) == [[0, 5], [1, 5]]


def test_transform_refused_outside_working_area():
    ed = start()
    select(ed, 0, 2)
    ed.run(keys("z") + tap(0, 0) + typed("1000"))
    assert "outside the working area" in ed.message
    assert pts(ed, 0) == ORIGINAL[0]


def test_background_classification():
    ed = start()
    ed.run(keys("g"))
    select(ed, 3, 3)
    ed.run(keys("l") + tap(0, 0) + tap(3, 0))
    styles = [(d.style, d.points.tolist()) for d in ed.display_list()]
    assert ("old", ORIGINAL[1]) in styles                 # faint purple former position
    assert ("bright", [[3, 1], [4, 1]]) in styles          # moved: normal brightness
    assert ("dim", ORIGINAL[0]) in styles and ("dim", ORIGINAL[2]) in styles
    assert len(styles) == 4
    ed.run(keys("g"))  # toggled off: plain display
    assert {d.style for d in ed.display_list()} == {"normal"}


def test_edit_mode_has_no_undo_and_back_to_drawing():
    ed = start()
    ed.run(keys("u"))
    assert "move back" in ed.message
    ed.feed(Key("e"))
    assert ed.mode == "draw"


@pytest.mark.parametrize("key", ["m", "l", "s", "t", "f", "p", "j", "d", "i", "z", "y", "k",
                                 "h", "x", "b", "a"])
def test_commands_on_an_empty_drawing_do_not_crash(key):
    ed = Editor()
    ed.run(keys("e", key) + tap(0, 0) + tap(1, 1) + typed("2") + typed("2"))
    assert ed.drawing.chains == []


def test_cursor_marks_for_the_front():
    ed = start()
    ed.run(tap(1.1, 0.9))  # square snaps to (1, 1)
    marks = dict((k, p.tolist()) for k, p in ed.cursors())
    assert marks == {"stylus": [1.1, 0.9], "square": [1, 1], "triangle": [2, 2]}
