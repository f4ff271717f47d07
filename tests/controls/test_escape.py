"""Esc and the window's close quit every windowed program: the harness turns Esc into a
close (the target's may_close() asks first) unless the program reads Esc itself, and
those programs leave on Esc too, asking y/n/Esc where there is unsaved work."""

from __future__ import annotations

from camlab88.emulator.host_input import KeyDown, KeyUp, Quit
from tests.controls.fakes import FakeClock, FakeWindow, harness_with
from tests.support.targets import Counter


def esc() -> list:
    return [KeyDown("escape", "\x1b"), KeyUp("escape")]


def test_escape_quits_a_program_that_does_not_read_it() -> None:
    target = Counter(100)
    h = harness_with(target, FakeWindow({3: esc()}), FakeClock())
    h.run()
    assert h.quit and h.ticks == 3 and target.got == []


def test_escape_asks_first_where_the_program_may_refuse_the_close() -> None:
    class Unsaved(Counter):
        def may_close(self) -> bool:
            return False  # unsaved work: the program asks (and here is told to stay)

    h = harness_with(Unsaved(10), FakeWindow({3: esc(), 5: [Quit()]}), FakeClock())
    h.run()
    assert not h.quit and h.ticks == 10


def test_escape_goes_to_a_program_that_reads_it() -> None:
    target = Counter(10)
    target.escape_is_a_key = True
    h = harness_with(target, FakeWindow({3: esc()}), FakeClock())
    h.run()
    assert not h.quit and target.got == esc()


def test_the_targets_that_read_escape_say_so() -> None:
    from camlab88.emulator.harness.rainbow import RainbowTarget
    from camlab88.emulator.harness.sigma import PeriodTarget, SigmaProgramTarget
    from camlab88.emulator.harness.sigma_line import SigmaLineTarget

    assert SigmaProgramTarget.escape_is_a_key  # KAS: Esc cancels, or asks before leaving
    assert SigmaLineTarget.escape_is_a_key     # a terminal key the host program reads
    assert not getattr(PeriodTarget, "escape_is_a_key", False)  # kas view: Esc quits
    assert not RainbowTarget.escape_is_a_key   # rainbow run, snooker replay: Esc quits


def test_snooker_escape_asks_y_n_escape_before_leaving() -> None:
    from camlab88.apps.snooker.program.program import Program
    from camlab88.emulator.machine import RainbowMachine
    from tests.snooker_program.helpers import feed

    rainbow = RainbowMachine()
    p = Program(rainbow.client)
    feed(rainbow, p, "move 300 420\nwait 1\nkey n\nwait 1")
    assert p.mode == "idle"
    feed(rainbow, p, "key escape\nwait 1")
    assert p.mode == "exit" and "escape = stay" in p.help_text and not p.done
    feed(rainbow, p, "key escape\nwait 1")  # stay
    assert p.mode == "idle" and not p.done
    feed(rainbow, p, "key escape\nwait 1\nkey n\nwait 1")  # leave without saving
    assert p.done


def test_ca_escape_closes_a_question_first_then_leaves() -> None:
    from tests.ca_program.driver import Driver

    d = Driver()
    d.leave_editing()
    d.main("Load pattern")
    assert d.program.dialogue is not None
    d.run("key escape\nframes 1")
    assert d.program.dialogue is None and not d.program.finished
    d.run("key escape\nframes 1")
    assert d.program.finished


def test_the_help_says_what_esc_does_for_each_kind_of_program() -> None:
    from camlab88.emulator.harness.help import key_lines

    for own, want in ((False, ("Esc, close", "quit (asks first where there is unsaved work)")),
                      (True, ("Esc", "the program's own key"))):
        target = Counter(3)
        target.escape_is_a_key = own
        h = harness_with(target, FakeWindow(), FakeClock())
        h.run()
        assert want in dict(key_lines(h))["Emulator controls"]
