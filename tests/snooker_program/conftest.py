from __future__ import annotations

from pathlib import Path

import pytest

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker_program"


@pytest.fixture
def rainbow():
    from camlab88.emulator.machine import RainbowMachine

    return RainbowMachine()


@pytest.fixture
def prog(rainbow):
    """The snooker program on the Rainbow, the cursor resting on bare cloth."""
    from camlab88.apps.snooker.program.program import Program
    from tests.snooker_program.helpers import EMPTY, feed

    p = Program(rainbow.client)
    feed(rainbow, p, f"move {EMPTY[0]} {EMPTY[1]}\nwait 1")
    return p
