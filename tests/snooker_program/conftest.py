from __future__ import annotations

from pathlib import Path

import pytest

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker_program"


@pytest.fixture
def rainbow():
    from camlab88.emulator.machine import RainbowMachine

    return RainbowMachine()
