"""A bounded record of protocol trace events, shared by both devices' API objects."""

from __future__ import annotations

from collections import deque
from collections.abc import Iterator

from camlab88.emulator.protocol_trace import TraceEvent

MAX_EVENTS = 100_000  # the most recent orders kept (a long session must not grow memory)
MAX_PROBLEMS = 1_000  # the first warnings kept


class Trace:
    """The decoded orders so far (the most recent MAX_EVENTS) and the first MAX_PROBLEMS
    warnings; ``problem_count`` counts all of them."""

    def __init__(self) -> None:
        self.events: deque[TraceEvent] = deque(maxlen=MAX_EVENTS)
        self.problems: list[TraceEvent] = []
        self.problem_count = 0

    def add(self, ev: TraceEvent) -> None:
        self.events.append(ev)
        if ev.warning is not None:
            self.problem_count += 1
            if len(self.problems) < MAX_PROBLEMS:
                self.problems.append(ev)

    def __iter__(self) -> Iterator[TraceEvent]:
        return iter(self.events)

    def __len__(self) -> int:
        return len(self.events)

    def __getitem__(self, i: int) -> TraceEvent:
        return self.events[i]

    def orders(self) -> list[str]:
        """The order names in sequence (handy in asserts)."""
        return [ev.order for ev in self.events]
