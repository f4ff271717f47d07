"""Replay a recording: into a live line, or as an endpoint a device reads from directly.

Either way the bytes arrive at exactly the recorded virtual times, so a deterministic device
fed from a replay, and read at the same times, ends in the same state as in the original.
"""

from __future__ import annotations

from fractions import Fraction

from camlab88.protocols.link.clock import TimeLike, VirtualClock, to_time
from camlab88.protocols.link.line import Endpoint
from camlab88.protocols.link.recording import Recording


def replay_into(recording: Recording, endpoint: Endpoint, direction: str | None = None) -> int:
    """Schedule the recorded chunks of ``direction`` (default: the one ``endpoint`` sends on)
    as writes from ``endpoint`` at their recorded start times; returns the bytes scheduled.

    The line's clock must not yet be past the first chunk. Flow-control bytes are replayed
    as they were on the wire."""
    if recording.settings != endpoint.line.settings:
        raise ValueError(
            f"recording is {recording.settings}, the line is {endpoint.line.settings}"
        )
    direction = direction or endpoint.direction
    ct = recording.settings.char_time
    total = 0
    for entry in recording.exact_entries:
        if entry.direction != direction:
            continue
        endpoint.write(entry.data, at=entry.t - len(entry.data) * ct)
        total += len(entry.data)
    return total


class ReplayEndpoint:
    """Reads like the receiving side of an Endpoint, from a recording of ``direction``.

    Bytes the device writes back are counted and discarded (the recording already holds
    what the other end did)."""

    def __init__(
        self, recording: Recording, direction: str = ">", clock: VirtualClock | None = None
    ) -> None:
        self.recording = recording
        self.clock = clock or VirtualClock()
        self._ct = recording.settings.char_time
        self._runs = [(t - (len(d) - 1) * self._ct, d) for t, d in recording.arrivals(direction)]
        self._next = 0
        self.written = 0

    def read_timed(
        self, until: TimeLike | None = None, *, exact: bool = False
    ) -> list[tuple[float, bytes]] | list[tuple[Fraction, bytes]]:
        horizon = self.clock.exact if until is None else to_time(until)
        out: list[tuple[Fraction, bytes]] = []
        while self._next < len(self._runs):
            first, data = self._runs[self._next]
            if first > horizon:
                break
            n = min(len(data), int((horizon - first) // self._ct) + 1)
            last = first + (n - 1) * self._ct
            if out and out[-1][0] + self._ct == first:
                out[-1] = (last, out[-1][1] + data[:n])  # back to back: one run, as a line reads
            else:
                out.append((last, data[:n]))
            if n < len(data):
                self._runs[self._next] = (first + n * self._ct, data[n:])
                break
            self._next += 1
        if exact:
            return out
        return [(float(t), d) for t, d in out]

    def read(self, until: TimeLike | None = None) -> bytes:
        return b"".join(d for _, d in self.read_timed(until, exact=True))

    def write(self, data: bytes) -> float:
        self.written += len(data)
        return self.clock.now

    @property
    def finished(self) -> bool:
        return self._next >= len(self._runs)
