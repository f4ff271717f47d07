"""Ending "Fast forward": Step mode or Auto mode goes back to the display
frequency in use before it, and the next shown generation is that many on."""

from __future__ import annotations

import pytest

from camlab88.apps.ca.program.program import Options
from tests.ca_program.driver import Driver


@pytest.mark.parametrize("mode", ["Step mode", "Auto mode"])
def test_ending_fast_forward_restores_the_display_frequency(mode: str) -> None:
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    d.program.frequency = 3
    d.main("Fast forward")
    d.frames(4)
    assert d.program.frequency > 3 * 8  # doubled with every generation shown
    d.main(mode)
    assert d.program.frequency == 3 and not d.program.fast_forward
    g = d.program.session.generation
    d.program.commit()  # show the next generation
    assert d.program.session.generation == g + 3  # not the doubled look-ahead


def test_fast_forward_twice_keeps_the_first_frequency() -> None:
    d = Driver(Options(pattern="glider"))
    d.leave_editing()
    d.program.frequency = 5
    d.main("Fast forward")
    d.frames(2)
    d.main("Fast forward")  # chosen again while running: still ends at 5
    d.frames(2)
    d.main("Step mode")
    assert d.program.frequency == 5
