"""Save / load state round trip, and its errors."""

from __future__ import annotations

import numpy as np
import pytest

from emulator.sigma import Terminal
from tests.sigma.streams import gks_plot, pgplot_plot


@pytest.mark.parametrize("model", ["t5684", "t5688"])
def test_save_load_round_trip_continues_identically(model: str) -> None:
    data = gks_plot(high_res=model == "t5688") + pgplot_plot()
    cut = len(data) // 2
    a = Terminal(model)
    a.feed(data[:cut])
    saved = a.save_state()
    b = Terminal(model)
    b.load_state(saved)
    assert b.save_state() == saved
    # a partly received order is not saved, so continue from a clean order boundary
    a.feed(b"\r+-*/GI100100")
    b.feed(b"\r+-*/GI100100")
    a.feed(data[cut:])
    b.feed(data[cut:])
    assert np.array_equal(a.frame(), b.frame()) and np.array_equal(a.planes, b.planes)
    assert a.reg == b.reg


def test_load_state_errors_are_clear() -> None:
    t = Terminal("t5684")
    with pytest.raises(ValueError, match="bad magic"):
        t.load_state(b"nonsense")
    saved = Terminal("t5688").save_state()
    with pytest.raises(ValueError, match="is for t5688"):
        t.load_state(saved)
    with pytest.raises(ValueError, match="corrupt"):
        t.load_state(t.save_state()[:-40])
