"""The interactive program's jumps (issue 17): look-ahead by HashLife, "Go to generation N"
and the doubling "Fast forward", on the emulated Rainbow (headless)."""

from __future__ import annotations

import numpy as np

from camlab88.apps.ca import log
from camlab88.apps.ca.program import stepping
from camlab88.apps.ca.program.menus import JUMP_ITEMS, MAIN_ITEMS, MainMenu
from camlab88.apps.ca.program.program import Options
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
    menu = MainMenu(d.machine.client, lut_page=13, jumps=True)
    assert menu.items == MAIN_ITEMS + JUMP_ITEMS and menu.width == 3 * 144
    menu.open(400, 300)
    x, y = menu.x + 2 * 144 + 10, menu.y + 18 + 5  # third column, second row
    assert menu.track(x, y) == "Fast forward"
    assert menu.track(x, y + 18) is None  # the column's empty rest
    assert menu.close() is None


def test_go_to_generation_through_the_menu_equals_the_direct_engine() -> None:
    d = Driver(Options(pattern="acorn"))
    d.leave_editing()
    ref = d.program.session.engine.copy()
    d.main("Go to generation")  # middle press, move to the third column, release
    assert d.program.asking is not None and d.program.asking.prompt == "Go to generation N ="
    d.run("key backspace\n" * 4 + "frames 1")
    d.type("2500")  # the offered default (1000) replaced by typing
    e = d.program.session.engine
    assert e.generation == 2500 and d.program.said[-1] == "Generation 2500"
    ref.step_direct(2500)
    assert e.same_state(ref) and e.population == ref.population
    assert all(np.array_equal(a, b) for a, b in zip(e.cells(), ref.cells(), strict=True))


def test_fast_forward_through_the_menu_doubles_then_step_mode_stops_it() -> None:
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    d.main("Fast forward")
    assert d.program.auto and d.program.fast_forward
    d.frames(4)
    assert d.program.frequency > 8  # doubled with every generation shown
    g = d.program.session.generation
    assert g == sum(1 << i for i in range(g.bit_length()))  # 1 + 2 + 4 + ...
    d.main("Step mode")
    f = d.program.frequency
    assert not d.program.fast_forward and not d.program.auto
    d.frames(3)
    assert d.program.frequency == f


class _Clock:
    """A clock that moves two seconds each time it is read (and can act on a reading)."""

    def __init__(self, on_read=None) -> None:  # called with the reading count
        self.t, self.reads, self.on_read = 0.0, 0, on_read

    def __call__(self) -> float:
        self.reads += 1
        if self.on_read is not None:
            self.on_read(self.reads)
        self.t += 2.0
        return self.t


def test_a_long_go_to_generation_shows_a_progress_bar() -> None:
    d = Driver(Options(pattern="gosper_gun"))
    d.leave_editing()
    d.program.clock = _Clock()
    d.program._start(stepping.go_to_generation(d.program))
    d.type("100000")
    bars = [s for s in d.program.said if s.startswith("Go to generation 100000: generation")]
    assert bars and all("%   Escape stops" in s and "[#" in s for s in bars)
    assert d.program.said[-1] == "Generation 100000"
    assert d.program.session.generation == 100000


def test_escape_stops_a_long_go_to_generation_and_keeps_the_shown_state() -> None:
    from camlab88.protocols.rainbow.events import KeyEvent

    d = Driver(Options(pattern="gosper_gun"))
    d.leave_editing()
    shown = d.program.session.engine.copy()
    # Escape arrives while the jump runs (the clock's third reading is inside it)
    d.program.clock = _Clock(lambda n: n == 3 and d.machine.post(KeyEvent(0, "escape", "")))
    d.program._start(stepping.go_to_generation(d.program))
    d.type("100000")
    assert d.program.said[-1].startswith("Go to generation 100000: stopped at generation 0")
    assert d.program.session.engine.same_state(shown)
    assert d.program.dialogue is None
    d.frames(2)  # the program runs on: input is read again, nothing was left pending
    assert d.program.session.generation == 0
