"""A Rainbow command-stream recording (``rainbow run --record-stream``) fed to a fresh
Rainbow as a harness target, so ``rainbow replay`` has the controls of every window (F5
pause, F6 one frame, F7/F8 speed, F11 the inspector, F12 a screenshot; --speed, --video,
--inspect-out). One device frame a tick, 50 a second; the replay itself runs in lockstep
(base.lockstep): it goes on only when the harness asks for the next frame, so a pause holds
it between two frames."""

from __future__ import annotations

from fractions import Fraction
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import numpy as np

    from camlab88.emulator.host_input import HostEvent
    from camlab88.protocols.rainbow.recording import Recording, ReplayResult

FPS = 50  # the Rainbow's frame rate: one wait_frame of the recording a frame


class StreamReplay:
    """The target; ``result`` is the replay's ReplayResult once every entry has been fed
    (None while it runs, or when the run was stopped before the end)."""

    title = "camlab88 Rainbow (replay)"
    keys = "the recording drives the Rainbow; Esc or close: stop"
    fps = FPS

    def __init__(self, rec: Recording, strict: bool = False) -> None:
        from camlab88.base.lockstep import lockstep
        from camlab88.emulator.machine import RainbowMachine

        self.rec = rec
        self.machine = RainbowMachine(strict_memory=strict)  # the inspector finds it here
        self.size = (768, 576)
        self.result: ReplayResult | None = None
        self.k = 0
        self.last: Any = None
        self._frames = lockstep(self._feed)

    def _feed(self, show: Any) -> None:
        self.machine.show_frames(show)
        self.result = self.machine.replay(self.rec)

    def handle_events(self, events: list[HostEvent]) -> None:
        """The recording's input events drive the Rainbow, not the window's."""

    def tick(self) -> bool:
        frame = next(self._frames, None)
        if frame is None:  # every entry fed
            return False
        self.last, self.k = frame, self.k + 1
        return True

    def frame(self) -> np.ndarray:
        return self.last if self.last is not None else self.machine.frame()

    def time(self) -> Fraction:
        return Fraction(self.k, FPS)

    def finish(self) -> None:
        """Stopped early (the window closed): the feeding thread ends."""
        self._frames.close()
