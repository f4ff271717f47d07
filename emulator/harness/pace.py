"""The frame limiter: the wall clock follows virtual time at a speed (1 = period speed,
None = flat out).  Changing the speed or resuming from a pause re-anchors the clocks, so
the run neither bursts to catch up nor stalls; a run that merely falls behind (a slow
machine, a busy tick) catches up, so a long paced run takes its period time."""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction


class Pacer:
    """``pace(t)`` sleeps until virtual time ``t`` is due on the wall clock."""

    def __init__(self, speed: float | None, monotonic: Callable[[], float],
                 sleep: Callable[[float], None]) -> None:
        if speed is not None and not speed > 0:
            raise ValueError(f"speed must be positive or None (flat out), not {speed!r}")
        self.speed = speed
        self._monotonic, self._sleep = monotonic, sleep
        self._anchor: tuple[float, float] | None = None  # (virtual s, wall s)
        self._flat: tuple[float, float] | None = None    # where flat-out running began
        self.slept = 0.0

    def pace(self, t: Fraction | float) -> None:
        virtual, now = float(t), self._monotonic()
        if self.speed is None:
            if self._flat is None:
                self._flat = (virtual, now)
            return
        if self._anchor is None:
            self._anchor = (virtual, now)
        v0, w0 = self._anchor
        wait = w0 + (virtual - v0) / self.speed - now
        if wait > 0:
            self._sleep(wait)
            self.slept += wait

    def release(self) -> None:
        """Virtual time ran ahead with nothing to wait for (a live line busy with bytes):
        the wall clock is not owed that time; pacing starts again from wherever ``pace`` is
        next called."""
        self._anchor = None

    def rebase(self, t: Fraction | float) -> None:
        """Virtual time ``t`` is due now (after a pause or a change of speed)."""
        now = self._monotonic()
        self._anchor = (float(t), now)
        self._flat = (float(t), now)

    def set_speed(self, speed: float | None, t: Fraction | float) -> None:
        self.speed = speed
        self.rebase(t)

    def achieved(self, t: Fraction | float) -> float | None:
        """Virtual seconds per wall second since flat-out running began (None: unknown)."""
        if self._flat is None:
            return None
        v0, w0 = self._flat
        wall = self._monotonic() - w0
        return (float(t) - v0) / wall if wall > 0 and float(t) > v0 else None
