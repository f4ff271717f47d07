"""Wiring helpers: a device plus a client talking to it in process (optionally recorded)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from camlab88.emulator.rainbow.device import Rainbow
from camlab88.emulator.rainbow.executor import Executor
from camlab88.protocols.rainbow.client import RainbowClient
from camlab88.protocols.rainbow.events import Event
from camlab88.protocols.rainbow.recording import Recording, RecordingTransport, ReplayResult, replay
from camlab88.protocols.rainbow.transport import LoopbackTransport


@dataclass
class Session:
    device: Rainbow
    executor: Executor
    client: RainbowClient
    recorder: RecordingTransport | None = None

    def inject(self, event: Event) -> None:
        """Host input -> the device's input controller (and the recording, if any)."""
        queued = self.device.post_event(event)
        if self.recorder is not None:
            self.recorder.record_input(queued)


def in_process(device: Rainbow | None = None, record: bool = False,
               on_frame: Callable[[np.ndarray], None] | None = None) -> Session:
    device = device or Rainbow()
    ex = Executor(device, on_frame)
    transport = LoopbackTransport(ex.handle)
    recorder = RecordingTransport(transport) if record else None
    return Session(device, ex, RainbowClient(recorder or transport), recorder)


def replay_on(rec: Recording, device: Rainbow | None = None) -> tuple[Rainbow, ReplayResult]:
    """Replay a recording on a fresh device; the result lists any reply that differs."""
    device = device or Rainbow()
    ex = Executor(device)
    result = replay(rec, ex.handle, device.post_event)
    return device, result
