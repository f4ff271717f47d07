"""Virtual time: exact (rational) seconds that advance only when told to."""

from __future__ import annotations

from fractions import Fraction
from numbers import Rational

TimeLike = float | int | Fraction

# Floats are read as the nearest fraction with a denominator up to this bound, so 0.04 is
# exactly 1/25 and 1/960 (as a float) is exactly 1/960; pass a Fraction to be exact.
FLOAT_DENOMINATOR_LIMIT = 10**7


def to_time(value: TimeLike) -> Fraction:
    """Convert a time given in seconds to an exact Fraction (see FLOAT_DENOMINATOR_LIMIT)."""
    if isinstance(value, Fraction):
        return value
    if isinstance(value, bool):
        raise TypeError("a time cannot be a bool")
    if isinstance(value, int | Rational):
        return Fraction(value)
    if isinstance(value, float):
        if value != value or value in (float("inf"), float("-inf")):
            raise ValueError(f"time must be finite, not {value!r}")
        return Fraction(value).limit_denominator(FLOAT_DENOMINATOR_LIMIT)
    raise TypeError(f"time must be a number of seconds, not {type(value).__name__}")


class VirtualClock:
    """A clock that moves only forward, only when advanced; ``now`` is float seconds."""

    def __init__(self, start: TimeLike = 0) -> None:
        self._now = to_time(start)

    @property
    def now(self) -> float:
        return float(self._now)

    @property
    def exact(self) -> Fraction:
        """The current time as an exact Fraction of a second."""
        return self._now

    def advance(self, dt: TimeLike) -> None:
        step = to_time(dt)
        if step < 0:
            raise ValueError(f"the clock cannot go backwards (advance by {dt!r})")
        self._now += step

    def advance_to(self, t: TimeLike) -> None:
        target = to_time(t)
        if target < self._now:
            raise ValueError(f"the clock cannot go backwards (from {self.now!r} s to {t!r} s)")
        self._now = target

    def save_state(self) -> list[int]:
        """The time as [numerator, denominator] (JSON-able, exact)."""
        return [self._now.numerator, self._now.denominator]

    def load_state(self, state: object) -> None:
        """Set the time from save_state()'s value (a restore may go backwards)."""
        if not (isinstance(state, list) and len(state) == 2
                and all(type(v) is int for v in state) and state[0] >= 0 and state[1] > 0):
            raise ValueError(f"clock state {state!r} is not [numerator, denominator] >= 0")
        self._now = Fraction(state[0], state[1])

    def __repr__(self) -> str:
        return f"VirtualClock(now={self._now})"
