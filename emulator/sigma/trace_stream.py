"""Trace a whole Sigma stream file (raw bytes sent back to back from t = 0, or a link
recording's host-to-terminal bytes at their recorded times) through a terminal."""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction
from typing import Any

import numpy as np

from camlab88.emulator.protocol_trace import TraceEvent
from camlab88.emulator.sigma.terminal import Terminal
from camlab88.emulator.sigma.trace import SigmaTracer


def byte_times(got: Any, char_time: Fraction) -> np.ndarray:
    """Arrival time (s) of every host-to-terminal byte of what
    protocols.sigma.stream_file.read_stream_file gave: raw bytes back to back from t = 0,
    a recording's bytes at their recorded times."""
    if isinstance(got, bytes):
        return np.arange(1, len(got) + 1, dtype=np.float64) * float(char_time)
    ct = float(got.settings.char_time)
    parts = [float(t) - np.arange(len(d) - 1, -1, -1, dtype=np.float64) * ct
             for t, d in got.arrivals(">")]
    return np.concatenate(parts) if parts else np.zeros(0)


class StreamTracer:
    """A tracer for a stream fed in pieces (whole, or period by period)."""

    def __init__(self, term: Terminal, got: Any, char_time: Fraction,
                 sink: Callable[[TraceEvent], None], strict: bool = False) -> None:
        self.tracer = SigmaTracer(term, sink, strict)
        self.times = byte_times(got, char_time)

    def feed(self, data: bytes) -> None:
        off = self.tracer.offset
        self.tracer.feed(data, times=self.times[off:off + len(data)])
