"""The host program and a terminal joined by the 9600-baud line (virtual clock).

The terminal is whatever the caller plugs in (the command wires the emulated T5688): it
only has to take the bytes that arrive (``feed``), show its screen's LUT indices
(``indices``, row 0 at the bottom, as the Sigma's y axis points up) and its picture
(``frame``, RGB, row 0 at the top). The host writes each
frame's orders to the line; the line delivers them at 9600 baud; the frame's line time is
when its last byte arrives minus when its first was sent.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from apps.snooker.render.leaks import classify
from apps.snooker.render.sigma_host import SigmaFrame, SigmaHost
from protocols.link import LineSettings, SerialLine, VirtualClock


class TerminalLike(Protocol):
    def feed(self, data: bytes) -> None: ...

    def indices(self) -> np.ndarray: ...

    def frame(self) -> np.ndarray: ...


@dataclass(frozen=True)
class SentFrame:
    frame: SigmaFrame
    line_seconds: float  # time on the line for this frame's orders
    leaks: int  # fill colour where the host did not put it (leaks.classify)
    gaps: int  # other pixels the terminal shows wrong
    screen: np.ndarray  # (512, 768) uint8 indices the terminal shows, row 0 = top


class SigmaSession:
    def __init__(self, host: SigmaHost, terminal: TerminalLike,
                 settings: LineSettings | None = None) -> None:
        self.host, self.terminal = host, terminal
        self.clock = VirtualClock()
        self.line = SerialLine(settings or LineSettings(baud=9600), clock=self.clock)
        self.setup_seconds = self._send(host.setup())

    def _send(self, data: bytes) -> float:
        start = self.clock.exact
        self.line.host.write(data)
        end = self.line.host.drain_time_exact()
        self.clock.advance_to(end)
        self.terminal.feed(self.line.device.read())
        return float(end - start)

    def show(self, view: object, frame: int | None = None) -> SentFrame:
        f = self.host.frame(view, frame)
        seconds = self._send(f.data)
        screen = np.ascontiguousarray(self.terminal.indices()[::-1])
        leaks, gaps = classify(screen, f.intended, f.flat_colours)
        return SentFrame(f, seconds, leaks, gaps, screen)
