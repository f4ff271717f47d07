"""The input controller (the relic's keyboard/mouse/tablet 6809): stamps and queues events."""

from __future__ import annotations

from collections import deque
from dataclasses import replace

from camlab88.protocols.rainbow.events import (
    Event,
    KeyEvent,
    MouseEvent,
    TabletEvent,
    decode_events,
    encode_event,
)

QUEUE_LIMIT = 4096  # a program that never reads its events loses the oldest, never memory


class InputController:
    def __init__(self) -> None:
        self.queue: deque[Event] = deque(maxlen=QUEUE_LIMIT)
        self.mouse_x = 0
        self.mouse_y = 0
        self.buttons = 0
        self.dropped = 0

    def post(self, event: Event, now_ms: int) -> Event:
        """Queue an event, stamped with the device clock; returns the event as queued."""
        if isinstance(event, MouseEvent):
            self.mouse_x, self.mouse_y, self.buttons = event.x, event.y, event.buttons
        elif not isinstance(event, KeyEvent | TabletEvent):
            raise TypeError(f"not an input event: {event!r}")
        event = replace(event, t_ms=now_ms)
        if len(self.queue) == self.queue.maxlen:
            self.dropped += 1
        self.queue.append(event)
        return event

    def take(self, limit: int = 256) -> list[Event]:
        out = []
        while self.queue and len(out) < limit:
            out.append(self.queue.popleft())
        return out

    def save_state(self) -> dict:
        """The queue (encoded events), the pointer and the drop count, as JSON values."""
        return {"queue": "".join(encode_event(e).hex() for e in self.queue),
                "pointer": [self.mouse_x, self.mouse_y, self.buttons], "dropped": self.dropped}

    def load_state(self, state: dict) -> None:
        events = decode_events(bytes.fromhex(state["queue"]), "input state")
        x, y, buttons = (int(v) for v in state["pointer"])
        dropped = int(state["dropped"])
        self.queue.clear()
        self.queue.extend(events)
        self.mouse_x, self.mouse_y, self.buttons, self.dropped = x, y, buttons, dropped
