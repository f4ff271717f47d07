"""A Rainbow with its command stream: the device, the executor, a byte-stream port a host
program writes command frames to (``host``) and a pad-library client on that port
(``client``); ticked in 20 ms frames and saved and restored as one."""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction

import numpy as np

from camlab88.emulator.machine.state_file import MachineStateError, pack, unpack
from camlab88.emulator.protocol_trace import TraceEvent
from camlab88.emulator.rainbow.device import FRAME_MS, Rainbow
from camlab88.emulator.rainbow.executor import Executor
from camlab88.emulator.rainbow.trace import RainbowTracer
from camlab88.protocols.rainbow.client import RainbowClient
from camlab88.protocols.rainbow.events import Event
from camlab88.protocols.rainbow.transport import LoopbackTransport


class StreamPort:
    """The Rainbow's end of the command stream: command frames in (split anywhere),
    reply frames out. The stream is carried out as it arrives, so it is always drained."""

    def __init__(self, machine: RainbowMachine) -> None:
        self._machine = machine
        self._replies = bytearray()

    def write(self, data: bytes) -> float:
        self._replies += self._machine.executor.feed(bytes(data))
        return self.now

    def read(self) -> bytes:
        out, self._replies = bytes(self._replies), bytearray()
        return out

    @property
    def now(self) -> float:
        return self._machine.device.time_ms / 1000

    @property
    def exact(self) -> Fraction:
        return Fraction(self._machine.device.time_ms, 1000)

    def drained(self) -> bool:
        return True

    def drain_exact(self) -> Fraction:
        return self.exact


class RainbowMachine:
    """Device + executor + stream port (``host``) + pad-library client (``client``)."""

    FPS = 1000 // FRAME_MS

    def __init__(self, strict_memory: bool = False) -> None:
        self.strict_memory = strict_memory
        self._build(Rainbow(strict=strict_memory))
        self.client = RainbowClient(LoopbackTransport(self._call))

    def _build(self, device: Rainbow) -> None:
        tracer = getattr(getattr(self, "executor", None), "tracer", None)
        self.device = device
        self.executor = Executor(device)
        self.executor.tracer = tracer
        self.host = StreamPort(self)

    def _call(self, frame: bytes) -> bytes:
        self.host.write(frame)
        return self.host.read()

    # ------------------------------------------------------------------ time
    @property
    def now(self) -> float:
        return self.device.time_ms / 1000

    def tick(self, dt: float = FRAME_MS / 1000) -> int:
        """Show frames for ``dt`` seconds (whole 20 ms frames, at least one)."""
        n = max(1, round(dt * 1000 / FRAME_MS))
        for _ in range(n):
            self.executor.last_frame = self.device.frame(self.executor.last_frame)
        return n

    def frame(self) -> np.ndarray:
        """(576, 768, 3) uint8: the screen as it stands (latched LUT), row 0 = top."""
        return self.device.peek()

    def post(self, event: Event) -> None:
        """Host input into the device's input controller (stamped with the device time)."""
        self.device.post_event(event)

    # ------------------------------------------------------------------ traces
    def trace(self, sink: Callable[[TraceEvent], None] | None,
              strict: bool = False) -> RainbowTracer | None:
        """Report every command to ``sink`` (None: stop); ``strict`` raises ProtocolError at
        the first refused command or bad frame."""
        self.executor.tracer = None if sink is None else RainbowTracer(sink, strict)
        return self.executor.tracer

    # ------------------------------------------------------------------ state
    def save_state(self) -> bytes:
        """Device (graph, memory, LUTs, clock, input queue), client ids, stream position."""
        head, blobs = self.device.save_state()
        offset, pending = self.executor.decoder.position()
        head["client"] = list(self.client.ids())
        head["stream"] = {"offset": offset, "pending": pending.hex()}
        head["strict_memory"] = self.strict_memory
        return pack("rainbow", head, blobs)

    def load_state(self, data: bytes) -> None:
        """Continue from save_state()'s bytes; MachineStateError if they do not fit."""
        head, blobs = unpack(data, "rainbow")
        if head.get("strict_memory") != self.strict_memory:
            raise MachineStateError("machine state is for a Rainbow with "
                                    f"strict_memory={head.get('strict_memory')!r}")
        try:
            device = Rainbow(strict=self.strict_memory)
            device.load_state(head, blobs)
            nxt, arc, calls = (int(v) for v in head["client"])
            offset, pending = int(head["stream"]["offset"]), bytes.fromhex(
                head["stream"]["pending"])
        except (ValueError, KeyError, TypeError, IndexError) as exc:
            raise MachineStateError(f"machine state: {exc}") from None
        self._build(device)
        self.client.continue_from((nxt, arc, calls))
        self.executor.decoder.resume(offset, pending)
