"""The interactive program's jumps (issue 17): look-ahead by HashLife, "Go to generation N"
and the doubling "Fast forward", on the emulated Rainbow (headless)."""

from __future__ import annotations

from apps.ca import log
from apps.ca.program import stepping
from apps.ca.program.menus import JUMP_ITEMS, MAIN_ITEMS, MainMenu
from apps.ca.program.program import Options
from tests.ca_program.driver import Driver


def test_go_to_generation_jumps_and_writes_the_checkpoints_on_the_way(tmp_path) -> None:
    log_path = tmp_path / "session.log"
    d = Driver(Options(pattern="gosper_gun", log=str(log_path), checkpoint=1000))
    d.leave_editing()
    ref = d.program.session.engine.copy()
    d.program._start(stepping.go_to_generation(d.program))
    d.type("3000")
    e = d.program.session.engine
    assert e.generation == 3000 and d.program.said[-1] == "Generation 3000"
    ref.step_direct(3000)
    assert e.same_state(ref)
    for gen in (1000, 2000, 3000):  # checkpoints after jumps equal stepped states
        back = log.read_checkpoint(log.checkpoint_path(str(log_path), gen))
        assert back.generation == gen
    assert log.read_checkpoint(log.checkpoint_path(str(log_path), 3000)).same_state(ref)


def test_go_to_an_earlier_generation_is_refused_clearly() -> None:
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    d.program._start(stepping.go_to_generation(d.program))
    d.type("-5")
    assert "from 0 on" in d.program.said[-1] and d.program.session.generation == 0


def test_fast_forward_doubles_the_display_frequency() -> None:
    assert [stepping.next_frequency(f, True) for f in (1, 2, 64)] == [2, 4, 128]
    assert stepping.next_frequency(5, False) == 5
    assert stepping.next_frequency(stepping.FAST_FORWARD_MAX, True) == \
        stepping.FAST_FORWARD_MAX
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    d.program._start(stepping.fast_forward(d.program))
    assert d.program.auto and d.program.fast_forward


def test_look_ahead_by_jumps_equals_stepping(tmp_path) -> None:
    d = Driver(Options(pattern="acorn", log=str(tmp_path / "s.log"), checkpoint=300))
    d.leave_editing()
    ref = d.program.session.engine.copy()
    shown, passed = stepping.ahead(d.program.session, 1000, None)
    ref.step_direct(1000)
    assert shown.same_state(ref)
    assert [e.generation for e in passed] == [300, 600, 900]


def test_the_main_menu_can_show_the_jumps_in_a_third_column() -> None:
    d = Driver()
    menu = MainMenu(d.session.client, lut_page=13, jumps=True)
    assert menu.items == MAIN_ITEMS + JUMP_ITEMS and menu.width == 3 * 144
    menu.open(400, 300)
    x, y = menu.x + 2 * 144 + 10, menu.y + 18 + 5  # third column, second row
    assert menu.track(x, y) == "Fast forward"
    assert menu.track(x, y + 18) is None  # the column's empty rest
    assert menu.close() is None
