"""Shared builders for the Rainbow tests."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.emulator.rainbow import Rainbow


def random_lut(seed: int = 7) -> np.ndarray:
    return np.random.default_rng(seed).integers(0, 256, (4096, 3), dtype=np.int64)


@pytest.fixture
def rainbow() -> Rainbow:
    r = Rainbow()
    r.set_lut(0, random_lut())
    return r
