"""The session model: the four editing methods, pattern load/erase, rule changes, logging,
checkpoints and replay of the resulting script."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.apps.ca import log
from camlab88.apps.ca.engine import Engine, Rect
from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import RuleError
from camlab88.apps.ca.session import Session

MAZE = Path(rules_path("maze")).read_text()
LIFE = Path(rules_path("life")).read_text()


def _session(tmp_path: Path | None = None, every: int = 0) -> Session:
    writer = log.LogWriter(tmp_path / "s.log", record_views=True) if tmp_path else None
    s = Session(Engine(), writer=writer, checkpoint_every=every)
    s.change_rules(MAZE, "maze")
    return s


def test_step_up_and_down_cycle_through_forms_with_rules() -> None:
    s = _session()
    assert [s.click(5, 5) for _ in range(5)] == [1, 2, 3, 0, 1]
    s.set_edit_mode("step_down")
    assert [s.click(5, 5) for _ in range(3)] == [0, 3, 2]


def test_set_value_erases_same_value_and_pick_up_colour() -> None:
    s = _session()
    s.set_edit_mode("set_value", 3)
    assert s.click(1, 1) == 3 and s.click(1, 1) == 0
    s.engine.set(2, 2, 2)
    assert s.click(2, 2) == 3  # overwrites any other value
    s.set_edit_mode("pick_up")
    s.engine.set(4, 4, 1)
    assert s.click(4, 4) == 1 and s.current == 1 and s.engine.get(4, 4) == 1  # picked
    assert s.click(7, 7) == 1  # dead cell gets the current colour
    assert s.click(7, 7) == 0  # same colour again: dead


def test_bad_rules_keep_the_old_rules_running() -> None:
    s = _session()
    old = s.engine.rules
    with pytest.raises(RuleError):
        s.change_rules("1 1 1 1 1 +1 +1 $", "broken")
    assert s.engine.rules is old


def test_load_same_point_again_erases() -> None:
    s = _session()
    s.change_rules(LIFE, "life")
    gun = read_pattern(pattern_path("gosper_gun"))
    assert s.load_pattern("gun", gun, 300, 300, "rot90") is True
    assert s.engine.population == 36
    assert s.load_pattern("gun", gun, 300, 300, "rot90") is False
    assert s.engine.population == 0


def test_whole_session_logged_checkpointed_and_replayed(tmp_path: Path) -> None:
    s = _session(tmp_path, every=10)
    s.change_rules(LIFE, "life")
    s.load_pattern("gun", read_pattern(pattern_path("gosper_gun")), 200, 200)
    s.set_zoom("8")
    for g in range(35):
        if g == 5:
            s.set_edit_mode("set_value", 1)
            for x in range(100, 103):
                s.click(x, 100)
        if g == 12:
            s.populate(Rect(150, 150, 170, 170), 0.4, {1: 1.0}, seed=3)
            s.pan_to(140, 140)
        if g == 20:
            s.advance_area(Rect(190, 190, 260, 260))
        if g == 25:
            s.advance_area(None)
            s.set_zoom("subpixel", 64)
        s.step()
    assert (tmp_path / "s.log30").exists()
    replayed = Session(Engine())
    e = log.start_from_script(str(tmp_path / "s.log"), 35, Engine,
                              on_view=replayed.apply_view_event)
    assert e.same_state(s.engine)
    assert (replayed.view.x, replayed.view.zoom, replayed.view.cells_per_pixel) == (
        140, "subpixel", 64)
    stats = s.statistics()
    assert stats["generation"] == 35 and stats["viewport"] == [140, 140, "subpixel"]


def test_centralise_and_zoom_limits() -> None:
    s = _session()
    s.engine.set_cells([1000, 1100], [2000, 2100], 1)
    s.centralise(47, 36)
    assert (s.view.x, s.view.y) == (1050 - 23, 2050 - 18)
    with pytest.raises(ValueError):
        s.set_zoom("subpixel", 2048)
    with pytest.raises(ValueError):
        s.set_edit_mode("smudge")


def test_same_point_again_erases_whatever_orientation_was_used() -> None:
    s = _session()
    glider = read_pattern(pattern_path("glider"))
    s.load_pattern("glider", glider, 50, 50, "rot90")
    s.load_pattern("glider", glider, 80, 50, "identity")
    assert s.load_pattern("glider", glider, 50, 50, "identity") is False
    assert s.engine.population == 5  # only the copy at (80, 50) is left
