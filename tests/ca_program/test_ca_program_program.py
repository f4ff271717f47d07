"""The ca program driven headless by scripted mouse and keyboard input (sections 7.3.1-2)."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.ca import library, log
from camlab88.apps.ca.engine import CENTRE, Rect
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.program.colours import DEAD_GREY, GRID_WHITE
from camlab88.apps.ca.program.menus import MAIN_ITEMS
from camlab88.apps.ca.program.program import Options
from camlab88.apps.ca.program.viewport import VIEW_H, VIEW_W
from tests.ca_program.driver import DATA, Driver
from tests.support.golden import assert_matches_golden


def test_start_screen_is_a_grey_and_white_grid_of_47_by_36_cells():
    d = Driver()
    d.frames(2)
    v = d.program.view
    assert (v.zoom, v.cells_across()) == (16, (47, 36))
    assert v.centre_cell() == (CENTRE, CENTRE)  # the centre of the plane
    f = d.frame
    # 752 x 576 of grid: each cell 15 x 15 grey with a 1-pixel white line right and below
    assert tuple(f[5, 5]) == DEAD_GREY
    grid = f[:VIEW_H, :VIEW_W]
    lines = np.all(grid == GRID_WHITE, axis=-1)
    xs = np.nonzero(lines.all(axis=0))[0]
    assert len(xs) == 47 and np.all(np.diff(xs) == 16)
    ys = np.nonzero(lines.all(axis=1))[0]
    assert len(ys) == 36 and np.all(np.diff(ys) == 16)
    assert d.program.editing and not d.program.auto  # edit mode, single-step mode
    assert_matches_golden(f, DATA / "start.png")


def test_pan_only_moves_arcs_and_draws_exposed_strips():
    d = Driver(Options(pattern="glider"), record=True)
    d.run("move 400 300\nframes 1")
    before = d.program.session.engine.cells()
    px, py = d.program.view.px, d.program.view.py
    d.commands_since_mark()
    d.run("press left 400 300\nframes 1")
    for x, y in ((390, 296), (377, 290), (377, 284), (390, 300)):
        d.run(f"move {x} {y}\nframes 1")
    d.run("release left 390 300\nframes 1")
    cmds = d.commands_since_mark()
    ops = {c.op.name for c in cmds}
    assert ops <= {"move", "put_pixels", "poll_events", "wait_frame"}, ops
    assert "put_pixels" in ops and "move" in ops
    # the grid followed the mouse: net (-10, 0) pixels
    assert (d.program.view.px, d.program.view.py) == (px + 10, py)
    # pixels drawn: only the strips exposed by each step, for both buffers
    drawn = sum(c.args[3] * c.args[4] for c in cmds if c.op.name == "put_pixels")
    exposed = (10 * VIEW_H + 13 * VIEW_H + 6 * (VIEW_W - 13) + 6 * (VIEW_W - 13)
               + 13 * VIEW_H)  # x:-10,-13,0,+13 ; y:-4,-6,-6,+16 (rows over the overlap)
    assert drawn <= 2 * (exposed + 16 * VIEW_W)
    assert drawn < VIEW_W * VIEW_H  # far less than one redraw
    after = d.program.session.engine.cells()
    assert all(np.array_equal(a, b) for a, b in zip(before, after))
    # the picture equals a fresh drawing of the same view
    ref = Driver(Options(pattern="glider"))
    ref.program.view.px, ref.program.view.py = d.program.view.px, d.program.view.py
    ref.program.changed()
    ref.program.display.pan()
    ref.run("move 390 300\nframes 1")  # the editing cursor where the mouse is
    assert np.array_equal(ref.frame, d.frame)


def test_zooms_change_the_cell_size_and_keep_the_centre():
    d = Driver(Options(pattern="gosper_gun"))
    d.leave_editing()
    for item, z in (("Zoom 8", 8), ("Zoom 4", 4), ("Zoom 2", 2), ("Zoom 1", 1)):
        d.main(item)
        assert d.program.view.zoom == z
        assert d.program.view.centre_cell() in ((CENTRE, CENTRE), (CENTRE - 1, CENTRE - 1),
                                                (CENTRE, CENTRE - 1), (CENTRE - 1, CENTRE))
    assert d.program.view.cells_across() == (752, 576)
    d.main("Zoom 8")
    f = d.frame[:VIEW_H, :VIEW_W]
    white = np.all(f == GRID_WHITE, axis=-1)
    assert len(np.nonzero(white.all(axis=0))[0]) == 94  # 94 x 72 cells at zoom 8
    d.main("Zoom subpixel")
    d.type("1024")
    assert d.program.view.zoom == 0 and d.program.view.cells_per_pixel == 1024
    d.main("Zoom subpixel")
    d.type("1000")  # not a square: refused, zoom unchanged
    assert "square" in d.program.said[-1] and d.program.view.cells_per_pixel == 1024
    # the gun shows as one or two density pixels, brighter than empty space
    f = d.frame[:VIEW_H - 50, :VIEW_W]  # above the message area
    assert 1 <= int(np.any(f != 0, axis=-1).sum()) <= 4


def test_edit_menu_methods_and_dragging():
    d = Driver()
    d.frames(1)
    e = d.program.session.engine
    c = (CENTRE, CENTRE)
    d.click_cell(*c)  # step up (the initial method): dead -> 1
    assert e.get(*c) == 1
    d.click_cell(*c)  # life has one life-form: wraps round to dead
    assert e.get(*c) == 0
    d.edit_menu("down")
    assert d.program.session.edit_mode == "step_down"
    d.click_cell(*c)
    assert e.get(*c) == 1
    d.edit_menu("left")  # set to value: its value menu
    d.pick("Life-form 1")
    assert (d.program.session.edit_mode, d.program.session.current) == ("set_value", 1)
    d.click_cell(CENTRE + 1, CENTRE)
    d.click_cell(CENTRE + 1, CENTRE)  # same value again erases
    assert e.get(CENTRE + 1, CENTRE) == 0
    # dragging with the right button paints every cell passed over
    x0, y0 = d.screen_of(CENTRE - 5, CENTRE + 3)
    x1, y1 = d.screen_of(CENTRE + 5, CENTRE + 3)
    d.run(f"move {x0} {y0}\ndrag right {x0} {y0} {x1} {y1} 3\nframes 1")
    assert all(e.get(x, CENTRE + 3) == 1 for x in range(CENTRE - 5, CENTRE + 6))
    d.edit_menu("right")  # pick up colour
    assert d.program.session.edit_mode == "pick_up"
    d.click_cell(*c)  # the current colour is 1 already: a living 1 -> dead
    assert e.get(*c) == 0
    assert_matches_golden(d.frame, DATA / "edited.png")
    # the centre item leaves edit mode; right button then steps a generation
    d.leave_editing()
    assert not d.program.editing
    g = d.program.session.generation
    d.run("click right 100 100\nframes 1")
    assert d.program.session.generation == g + 1


def test_main_menu_layout_and_do_nothing():
    d = Driver()
    d.leave_editing()
    d.run("press middle 300 300\nframes 1")
    menu = d.program.main_menu
    assert menu.open_ and MAIN_ITEMS[menu.highlighted] == "Do nothing"
    f = d.frame
    ox, oy = menu.x, menu.y
    d.run("release middle 300 300\nframes 1")
    assert not menu.open_ and d.program.session.generation == 0
    assert MAIN_ITEMS[:10][5] == "Do nothing" and MAIN_ITEMS[10] == "Centralise viewport"
    assert menu.width == 3 * 144  # the third column: HashLife's jumps
    assert_matches_golden(f[oy:oy + 180, ox:ox + menu.width], DATA / "main_menu.png")


def test_load_pattern_orientation_copies_and_erase():
    d = Driver()
    d.leave_editing()
    gun = read_pattern(library.pattern_path("glider"))
    e = d.program.session.engine
    d.place_pattern("glider", CENTRE, CENTRE, "rot90")
    d.click_cell(CENTRE + 10, CENTRE)  # a second copy, same orientation
    e = d.program.session.engine
    for x0 in (CENTRE, CENTRE + 10):
        xs, ys, ts = gun.placed(x0, CENTRE, "rot90")
        assert all(e.get(int(x), int(y)) == t for x, y, t in zip(xs, ys, ts))
    assert e.population == 2 * len(gun.xs)
    d.click_cell(CENTRE, CENTRE)  # the same point again erases that copy
    assert e.population == len(gun.xs)
    d.run("key escape\nframes 1")
    assert d.program.dialogue is None


def test_randomly_populate_statistics_and_modes():
    d = Driver()
    d.leave_editing()
    d.main("Randomly populate")
    d.click_cell(CENTRE - 10, CENTRE - 8)
    d.run("move 500 400\nframes 1")
    assert d.program.display.rubber.visible  # rubber band to the second corner
    d.click_cell(CENTRE + 9, CENTRE + 7)
    d.type("0.5")
    d.type("1:1")
    e = d.program.session.engine
    xs, ys, _ = e.cells()
    assert 60 < e.population < 260  # 20 x 16 cells at density 0.5
    assert xs.min() >= CENTRE - 10 and xs.max() <= CENTRE + 9
    assert ys.min() >= CENTRE - 8 and ys.max() <= CENTRE + 7
    d.main("Statistics")
    text = d.program.said[-1]
    assert f"Population   {e.population}" in text and "Generation   0" in text
    assert "Viewport     32745,32750 (47x36 cells, zoom 16)" in text
    box = e.bbox()
    assert f"{box.x0},{box.y0} .. {box.x1},{box.y1}" in text
    assert_matches_golden(d.frame, DATA / "statistics.png")
    # single-step mode: the next generation is ready before the click, shown by it
    d.run("click right 600 500\nframes 1")  # dismisses the statistics
    ready = d.program.pending
    assert ready is not None and ready.generation == 1
    d.step()
    assert d.program.session.generation == 1 and d.program.session.engine is ready
    d.main("Auto mode")
    g = d.program.session.generation
    d.frames(5)
    assert d.program.session.generation == g + 5  # one per frame
    d.main("Step mode")
    g = d.program.session.generation
    d.frames(3)
    assert d.program.session.generation == g
    d.main("Finish")
    assert d.program.finished


def test_change_rules_bad_file_keeps_old_rules(tmp_path):
    bad = tmp_path / "bad.rules"
    bad.write_text("1 1 1 1 1\n+1 +1 +1\n+1 |#X10\n$\n")
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    old = d.program.session.engine.rules
    d.main("Change rules")
    d.type(str(bad))
    assert d.program.session.engine.rules is old
    assert "bad.rules:" in d.program.said[-1] and "old rules" in d.program.said[-1]
    d.main("Change rules")
    d.type("overgrazing")
    assert d.program.session.engine.rules is not old
    assert len(d.program.session.engine.rules.forms) > 1


def test_clear_advance_area_and_alter_display():
    d = Driver(Options(pattern="gosper_gun"))
    d.leave_editing()
    e = d.program.session.engine
    n = e.population
    d.main("Advance area")
    d.pick("Advance a rectangle")
    d.click_cell(CENTRE, CENTRE)
    d.click_cell(CENTRE + 5, CENTRE + 5)
    assert e.advance_area == Rect(CENTRE, CENTRE, CENTRE + 5, CENTRE + 5)
    outside = [(x, y, t) for x, y, t in zip(*e.cells()) if not (x <= CENTRE + 5
                                                                  and y <= CENTRE + 5)]
    d.step(2)
    e = d.program.session.engine
    assert e.generation == 2
    assert all(e.get(x, y) == t for x, y, t in outside)  # frozen outside
    d.main("Alter display")
    d.pick("Monochrome")
    f = d.frame
    ys, xs = np.nonzero(np.all(f[:VIEW_H, :VIEW_W] == (255, 255, 255), axis=-1)
                        & np.all(f[:VIEW_H, :VIEW_W] != 0, axis=-1))
    assert len(ys) > 0
    d.main("Clear area")
    d.pick("Clear the entire grid")
    assert d.program.session.engine.population == 0 < n


def _edit_step_and_load_a_glider(d: Driver, edit_at: int, steps: int, load_at: int,
                                 orientation: str) -> None:
    """A logged session's interventions: an edited cell, ``steps`` generations, a loaded glider."""
    d.click_cell(CENTRE + edit_at, CENTRE + edit_at)
    d.leave_editing()
    d.step(steps)
    d.place_pattern("glider", CENTRE + load_at, CENTRE + load_at, orientation)
    d.run("key escape\nframes 1")


@pytest.mark.parametrize("every", [0, 5])
def test_log_replayed_as_script_reaches_the_same_generation(tmp_path, every):
    log_path = tmp_path / "session.log"
    d = Driver(Options(pattern="r_pentomino", log=str(log_path), record_pans=True,
                       checkpoint=every))
    _edit_step_and_load_a_glider(d, edit_at=6, steps=7, load_at=-8, orientation="flip_x")
    d.main("Alter display")
    d.pick("Display frequency")
    d.type("3")
    d.run("drag left 300 300 250 280 3\nframes 1")
    d.step(4)
    e = d.program.session.engine
    assert e.generation == 7 + 12
    if every:
        assert (tmp_path / "session.log15").exists()
    r = Driver(Options(script=str(log_path), start=e.generation, replay_pans=True))
    assert r.program.session.engine.same_state(e)
    assert r.program.view.top_left_cell() == d.program.view.top_left_cell()
    # without --start the program asks where to begin
    asked = Driver(Options(script=str(log_path)))
    assert asked.program.asking is not None and asked.program.asking.kind == "text"
    asked.type("8")
    assert asked.program.session.generation == 8 and asked.program.dialogue is None
    escaped = Driver(Options(script=str(log_path)))
    escaped.run("key escape\nframes 1")  # unanswered: the script's last generation
    last = max(ev.generation for ev in log.read_log(log_path))
    assert escaped.program.session.generation == last == 7
    # a script begun earlier picks up the later interventions as its generations come
    r2 = Driver(Options(script=str(log_path), start=3))
    r2.leave_editing()
    r2.step(e.generation - 3)
    assert r2.program.session.engine.same_state(e)


def test_huge_advance_area_and_far_pan_stay_drawable():
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    d.main("Advance area")
    d.pick("Advance a rectangle")
    d.click_cell(CENTRE - 2, CENTRE - 2)
    # pan a long way with the first corner fixed, then mark the far corner
    d.run("press left 700 500\nmove 10 10\nmove 700 500\nrelease left 700 500\nframes 1")
    d.run("press left 700 500\nmove 10 10\nrelease left 10 10\nframes 1")
    x, y = d.program.view.cell_at(700, 500)
    d.run("move 700 500\nclick right 700 500\nframes 1")
    assert d.program.session.engine.advance_area == Rect(CENTRE - 2, CENTRE - 2, x, y)
    assert x - CENTRE > 47
    d.main("Zoom 1")
    d.main("Centralise viewport")
    bx = d.program.session.engine.bbox()
    assert d.program.view.cell_visible(bx.x0, bx.y0)
    assert d.program.display.area.visible


def test_next_generation_is_recomputed_after_an_edit_and_grid_option():
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    first = d.program.pending
    assert first is not None and first.generation == 1  # computed before it is wanted
    d.main("Edit cells")
    d.click_cell(CENTRE - 6, CENTRE - 6)
    assert d.program.pending is None  # discarded by the edit
    d.leave_editing()
    again = d.program.pending
    want = d.program.session.engine.copy()
    want.step()
    assert again is not first and again.same_state(want)
    d.step()
    assert d.program.session.engine.same_state(want)
    # the grid: gap pixels white with the grid on, the dead colour with it off
    d.main("Alter display")
    d.pick("Grid off")
    assert tuple(d.frame[15, 5]) == DEAD_GREY
    d.main("Alter display")
    d.pick("Grid on")
    assert tuple(d.frame[15, 5]) == GRID_WHITE


def test_save_pattern_then_load_it_back(tmp_path):
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    box = d.program.session.engine.bbox()
    d.main("Save pattern")
    d.click_cell(box.x0 - 1, box.y0 - 1)
    d.click_cell(box.x1 + 1, box.y1 + 1)
    d.type(str(tmp_path / "mine"))
    d.click_cell(box.x0, box.y0)  # reference point
    saved = read_pattern(tmp_path / "mine.pat")
    assert saved.ref == (0, 0) and len(saved.xs) == 5
    d.main("Clear area")
    d.pick("Clear the entire grid")
    d.place_pattern(str(tmp_path / "mine.pat"), CENTRE, CENTRE, "identity")
    d.run("key escape\nframes 1")
    e = d.program.session.engine
    xs, ys, _ = e.cells()
    assert (int(xs.min()), int(ys.min())) == (CENTRE, CENTRE) and e.population == 5


def test_subpixel_pan_and_zoom_back():
    d = Driver(Options(pattern="acorn"))
    d.leave_editing()
    d.main("Zoom subpixel")
    d.type("16")
    d.run("drag left 400 300 300 250 5\nframes 1")
    assert d.program.view.side == 4
    d.main("Centralise viewport")
    d.main("Zoom 16")
    bx = d.program.session.engine.bbox()
    assert d.program.view.cell_visible((bx.x0 + bx.x1) // 2, (bx.y0 + bx.y1) // 2)


def test_set_to_value_with_many_life_forms_asks_for_a_number(tmp_path):
    """Over 28 life-forms the value is typed: cancelling is silent, and the value must be a
    life-form that has rules."""
    rules = tmp_path / "many.rules"
    forms = [*range(1, 30), 40]
    rules.write_text("".join(f"{n} 0 0 0 0 +{n}\n" for n in forms) + "$\n"
                     + "".join(f"{n} {n}\n" for n in forms))
    d = Driver(Options(rules=str(rules)))
    d.frames(1)
    d.edit_menu("left")
    assert d.program.asking is not None and d.program.asking.kind == "text"
    d.run("key escape\nframes 1")
    assert d.program.dialogue is None
    assert not any("None" in s for s in d.program.said)
    assert d.program.session.edit_mode == "step_up"
    for bad in ("35", "0", "-1"):
        d.edit_menu("left")
        d.type(bad)
        assert "has no rules" in d.program.said[-1] and d.program.session.edit_mode == "step_up"
    d.edit_menu("left")
    d.type("40")
    assert (d.program.session.edit_mode, d.program.session.current) == ("set_value", 40)
    d.click_cell(CENTRE, CENTRE)
    assert d.program.session.engine.get(CENTRE, CENTRE) == 40


PROB_RULES = """1 1 1 1 1 +1 +1 +1 +1 |16 +1 +1 +1 +1 $
#X12 1  #X13 1  3 50% 1 50% 0  #X11 50% 1 50% 0
"""


def _probabilistic_session(tmp_path, **kw) -> Driver:
    rules = tmp_path / "coin.rules"
    rules.write_text(PROB_RULES)
    d = Driver(Options(rules=str(rules), pattern="r_pentomino", log=str(tmp_path / "s.log"),
                       **kw))
    d.leave_editing()
    d.step(12)
    assert d.program.session.generation == 12
    return d


def test_log_records_edges_and_seed_and_a_replay_uses_them(tmp_path):
    """Section 8.1 outcomes depend on the seed: a replay without the flags must still
    reproduce the run; flags that disagree are warned about and overruled."""
    d = _probabilistic_session(tmp_path, edges="bounded", seed=12345)
    e = d.program.session.engine
    head = (tmp_path / "s.log").read_text().splitlines()[:3]
    assert head == [log.LOG_MAGIC, "edges bounded", "seed 12345"]
    r = Driver(Options(script=str(tmp_path / "s.log"), start=12))
    assert r.program.session.engine.same_state(e)
    assert (r.program.session.engine.edges, r.program.session.engine.seed) == ("bounded",
                                                                               12345)
    assert not any("Warning" in s for s in r.program.said)
    w = Driver(Options(script=str(tmp_path / "s.log"), start=12, edges="wrap", seed=1))
    assert w.program.session.engine.same_state(e)
    warnings = [s for s in w.program.said if s.startswith("Warning")]
    assert len(warnings) == 2 and "seed 12345" in warnings[1]


def test_same_file_for_log_and_script_continues_the_history(tmp_path):
    """Script S and Log S together: the session continues its own log, which keeps the
    replayed history; replaying the continued log reaches the continued state."""
    path = tmp_path / "s.log"
    d = Driver(Options(pattern="r_pentomino", log=str(path), checkpoint=5))
    _edit_step_and_load_a_glider(d, edit_at=9, steps=8, load_at=-12, orientation="identity")
    d.step(4)
    first = log.read_log(path)
    assert [ev.kind for ev in first] == ["rules", "load", "edit", "load"]
    assert (tmp_path / "s.log10").exists()
    # continue from generation 6: the load at 8 and the checkpoint at 10 are superseded
    c = Driver(Options(script=str(path), log=str(path), start=6, checkpoint=5))
    kept = log.read_log(path)
    assert kept == [ev for ev in first if ev.generation <= 6]
    assert not (tmp_path / "s.log10").exists() and (tmp_path / "s.log10.superseded").exists()
    assert (tmp_path / "s.log5").exists()
    c.leave_editing()
    c.step(2)
    c.click_cell(CENTRE + 20, CENTRE)  # step mode: not editing, so this steps again
    c.main("Clear area")
    c.pick("Clear a rectangle")
    a, b = c.screen_of(CENTRE - 3, CENTRE - 3), c.screen_of(CENTRE + 3, CENTRE + 3)
    c.run(f"move {a[0]} {a[1]}\nclick right {a[0]} {a[1]}\nmove {b[0]} {b[1]}\n"
          f"click right {b[0]} {b[1]}\nframes 1")
    c.step(6)
    cont = c.program.session.engine
    assert cont.generation == 15
    events = log.read_log(path)
    assert events[:len(kept)] == kept and events[-1].kind == "clear"
    r = Driver(Options(script=str(path), start=15))
    assert r.program.session.engine.same_state(cont)


def test_save_pattern_from_a_rectangle_across_the_seam(tmp_path):
    from camlab88.apps.ca.program import commands

    d = Driver()
    d.program.session.engine.set_cells([65534, 65535, 0], [100, 100, 100], 1)
    dialogue = commands.save_pattern(d.program)
    assert next(dialogue).kind == "rect"
    assert dialogue.send(commands.rect_from((65533, 99), (1, 101))).kind == "text"
    assert dialogue.send(str(tmp_path / "seam.pat")).kind == "point"
    with pytest.raises(StopIteration):
        dialogue.send((65535, 100))
    pat = read_pattern(tmp_path / "seam.pat")
    assert pat.cell_set() == {(0, 0, 1), (1, 0, 1), (2, 0, 1)}  # 3 cells, not 65535 wide
    assert pat.ref == (1, 0) and "Saved 3 cells" in d.program.said[-1]


def test_the_editing_cursor_stays_inside_the_visible_area():
    # section 7.3.1: the editing cursor is kept inside the visible area; over the band at
    # the right the right button edits the last visible cell of that row
    d = Driver()
    d.frames(1)
    e = d.program.session.engine
    d.run("move 766 300\nclick right 766 300\nframes 1")
    assert e.get(*d.program.view.cell_at(751, 300)) == 1 and e.population == 1


def test_centralise_viewport_brings_the_population_back_into_view():
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    d.run("drag left 700 500 10 10 5\nframes 1")  # pan the glider out of view
    bx = d.program.session.engine.bbox()
    centre = ((bx.x0 + bx.x1) // 2, (bx.y0 + bx.y1) // 2)
    assert not d.program.view.cell_visible(*centre)
    d.main("Centralise viewport")
    assert d.program.view.cell_visible(*centre)
    assert d.program.view.centre_cell() == pytest.approx(centre, abs=1)
