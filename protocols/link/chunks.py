"""Split a byte stream into the pieces that arrive in each period of line time."""

from __future__ import annotations

from collections.abc import Iterator

from camlab88.protocols.link.clock import TimeLike, to_time
from camlab88.protocols.link.settings import LineSettings


def chunks_by_period(
    data: bytes, settings: LineSettings, period: TimeLike, start: TimeLike = 0.0
) -> Iterator[tuple[int, bytes]]:
    """Yield ``(k, bytes)`` for every period k = 0, 1, ... up to the last byte's period.

    The stream is sent back to back from line time ``start``; byte i's last bit arrives at
    ``start + (i + 1) * char_time``. Period k is the half-open interval
    ``(start + k*period, start + (k+1)*period]``, so period k holds exactly the bytes that have
    arrived by the end of the period: feeding chunks 0..k gives the screen at time
    ``start + (k+1)*period``. Empty periods are yielded as ``b""`` so every frame is present.
    Arithmetic is exact (period 0.04 is 1/25 s; see clock.to_time).
    """
    p = to_time(period)
    if p <= 0:
        raise ValueError(f"period must be positive, not {period!r}")
    to_time(start)  # validates; periods are measured from start, so its value cancels out
    ct = settings.char_time
    # Bytes with (i + 1) * ct <= (k + 1) * p have arrived by the end of period k; in integers:
    # count = (k + 1) * p / ct = (k + 1) * num // den.
    ratio = p / ct
    num, den = ratio.numerator, ratio.denominator
    total = len(data)
    done = 0
    k = 0
    while done < total:
        upto = min(total, (k + 1) * num // den)
        yield k, bytes(data[done:upto])
        done = upto
        k += 1
