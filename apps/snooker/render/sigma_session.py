"""The host program on the 9600-baud line to a Sigma T5688 (virtual clock).

The program writes each frame's orders to its port and waits for the line (the link's
``wait``: whoever runs the machine runs it until everything has arrived); the frame's line
time is when its last byte arrives minus when its first was sent.  The screen's LUT indices,
read back afterwards, measure the colour leaks (leaks.classify).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.render.leaks import classify
from camlab88.apps.snooker.render.sigma_host import SigmaFrame, SigmaHost
from camlab88.protocols.link.port import BatchLink


@dataclass(frozen=True)
class SentFrame:
    frame: SigmaFrame
    line_seconds: float  # time on the line for this frame's orders
    leaks: int  # fill colour where the host did not put it (leaks.classify)
    gaps: int  # other pixels the terminal shows wrong
    screen: np.ndarray  # (512, 768) uint8 indices the terminal shows, row 0 = top


class SigmaSession:
    def __init__(self, host: SigmaHost, link: BatchLink) -> None:
        self.host, self.link = host, link
        self.setup_seconds = self._send(host.setup())

    def _send(self, data: bytes) -> float:
        start = self.link.port.now
        end = self.link.port.write(data)
        self.link.wait()
        return end - start

    def show(self, view: object, frame: int | None = None) -> SentFrame:
        f = self.host.frame(view, frame)
        seconds = self._send(f.data)
        screen = self.link.indices()
        leaks, gaps = classify(screen, f.intended, f.flat_colours)
        return SentFrame(f, seconds, leaks, gaps, screen)
