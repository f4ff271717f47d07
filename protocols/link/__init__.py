"""The serial line: line settings, a virtual clock, a paced two-way line, recording/replay
and transports (pty, TCP on loopback, any pyserial URL)."""

from __future__ import annotations

from camlab88.protocols.link.chunks import chunks_by_period
from camlab88.protocols.link.clock import VirtualClock, to_time
from camlab88.protocols.link.line import (
    DEVICE_TO_HOST,
    HOST_TO_DEVICE,
    XOFF,
    XON,
    Endpoint,
    SerialLine,
)
from camlab88.protocols.link.recording import Recorder, Recording, RecordingError, read_recording
from camlab88.protocols.link.replay import ReplayEndpoint, replay_into
from camlab88.protocols.link.settings import LineSettings
from camlab88.protocols.link.throttle import Throttle

__all__ = [
    "DEVICE_TO_HOST",
    "HOST_TO_DEVICE",
    "XOFF",
    "XON",
    "Endpoint",
    "LineSettings",
    "Recorder",
    "Recording",
    "RecordingError",
    "ReplayEndpoint",
    "SerialLine",
    "Throttle",
    "VirtualClock",
    "chunks_by_period",
    "read_recording",
    "replay_into",
    "to_time",
]
