"""Map virtual time to the wall clock for interactive use.

Pacing changes how fast a session plays, never what it shows: the caller still steps the
virtual clock on its own fixed grid; the throttle only sleeps so that virtual time does not
run ahead of the wall clock (times ``speed``).
"""

from __future__ import annotations

import time
from collections.abc import Callable

from camlab88.protocols.link.clock import TimeLike, to_time


class Throttle:
    """``pace(t)`` sleeps until the wall clock reaches virtual time ``t`` (scaled by speed).

    ``speed=None`` runs flat out (never sleeps). The first call anchors virtual to wall time.
    """

    def __init__(
        self,
        speed: float | None = 1.0,
        *,
        monotonic: Callable[[], float] = time.monotonic,
        sleep: Callable[[float], None] = time.sleep,
    ) -> None:
        if speed is not None and not speed > 0:
            raise ValueError(f"speed must be positive or None (flat out), not {speed!r}")
        self.speed = speed
        self._monotonic = monotonic
        self._sleep = sleep
        self._anchor: tuple[float, float] | None = None  # (virtual s, wall s)
        self.behind = 0.0  # how far the wall clock was past the target at the last pace()

    def wall_target(self, t: TimeLike) -> float:
        """The wall-clock time at which virtual time ``t`` is due."""
        if self.speed is None:
            return self._monotonic()
        virtual = float(to_time(t))
        if self._anchor is None:
            self._anchor = (virtual, self._monotonic())
        v0, w0 = self._anchor
        return w0 + (virtual - v0) / self.speed

    def pace(self, t: TimeLike) -> None:
        """Sleep until virtual time ``t`` is due; never sleeps when flat out or late."""
        if self.speed is None:
            return
        due = self.wall_target(t)
        wait = due - self._monotonic()
        self.behind = max(0.0, -wait)
        if wait > 0:
            self._sleep(wait)

    def reset(self) -> None:
        """Re-anchor at the next pace() (e.g. after a pause)."""
        self._anchor = None
