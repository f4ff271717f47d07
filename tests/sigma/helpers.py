"""Small helpers shared by the Sigma tests."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from camlab88.emulator.sigma import Terminal
from camlab88.protocols.sigma import Encoder

DATA = Path(__file__).resolve().parents[1] / "data" / "sigma"
FLAG = b"+-*/"


def run(stream: bytes, model: str = "t5684") -> Terminal:
    t = Terminal(model)
    t.feed(stream)
    return t


def graphics(*parts: bytes, model: str = "t5684") -> Terminal:
    """A terminal fed the graphics flag then the given parts."""
    return run(FLAG + b"".join(parts), model)


def enc(model: str = "t5684") -> Encoder:
    return Encoder(high_res=model == "t5688")


def lit(t: Terminal) -> set[tuple[int, int]]:
    """Device (x, y) of every non-zero pixel of the plane store."""
    ys, xs = np.nonzero(t.planes)
    return set(zip(xs.tolist(), ys.tolist()))
