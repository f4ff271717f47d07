"""A Rainbow with its command stream: the device, the executor, a byte-stream port a host
program writes command frames to (``host``) and a pad-library client (``client``, one call
one whole frame); ticked in 20 ms frames, optionally recorded, and saved and restored as
one. Every Rainbow program in camlab88 runs on this machine."""

from __future__ import annotations

import socket
from collections.abc import Callable
from fractions import Fraction
from pathlib import Path

import numpy as np

from camlab88.emulator.machine.state_file import MachineStateError, pack, unpack
from camlab88.emulator.protocol_trace import TraceEvent
from camlab88.emulator.rainbow.device import FRAME_MS, Rainbow
from camlab88.emulator.rainbow.errors import RainbowError
from camlab88.emulator.rainbow.executor import Executor
from camlab88.emulator.rainbow.scene import load_scene
from camlab88.emulator.rainbow.server import ServerStats, listen, serve
from camlab88.emulator.rainbow.trace import RainbowTracer
from camlab88.protocols.rainbow.client import RainbowClient
from camlab88.protocols.rainbow.events import Event
from camlab88.protocols.rainbow.recording import (
    Recording,
    RecordingTransport,
    ReplayResult,
    replay,
)
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
    """Device + executor + stream port (``host``) + pad-library client (``client``).

    ``strict_memory``: the relic's 512x256 video memory. ``record``: every client call, its
    reply and every input posted are written down in ``recording`` (a ``rainbow replay``
    file, and a session recording's command stream). ``on_frame`` is told each frame a
    program waits for (a window showing them)."""

    FPS = 1000 // FRAME_MS

    def __init__(self, strict_memory: bool = False, record: bool = False,
                 on_frame: Callable[[np.ndarray], None] | None = None) -> None:
        self.strict_memory = strict_memory
        self._on_frame = on_frame
        self._build(Rainbow(strict=strict_memory))
        # the client's calls are whole frames, each answered on its own (Executor.handle);
        # the byte stream of ``host`` is not involved, so a half-written stream never
        # swallows a call
        port = LoopbackTransport(self._call)
        self._recorder = RecordingTransport(port) if record else None
        self.client = RainbowClient(self._recorder or port)

    def _build(self, device: Rainbow) -> None:
        tracer = getattr(getattr(self, "executor", None), "tracer", None)
        self.device = device
        self.executor = Executor(device, self._on_frame)
        self.executor.tracer = tracer
        self.host = StreamPort(self)

    def _call(self, frame: bytes) -> bytes:
        return self.executor.handle(frame)

    def show_frames(self, on_frame: Callable[[np.ndarray], None] | None) -> None:
        """Tell ``on_frame`` each frame a program waits for from now on (None: stop)."""
        self._on_frame = self.executor.on_frame = on_frame

    @property
    def recording(self) -> Recording | None:
        """What crossed the client and the input so far (None: not recording)."""
        return None if self._recorder is None else self._recorder.recording

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

    def shown(self) -> np.ndarray:
        """The frame last shown (ONE buffer later frames are composed into: copy it to keep
        it), or the screen as it stands before any."""
        last = self.executor.last_frame
        return last if last is not None else self.device.peek()

    @property
    def frame_count(self) -> int:
        """Display frames shown since power-on (50 a second)."""
        return self.device.frame_count

    @property
    def compiles(self) -> int:
        """How often the pad graph has been compiled into bands."""
        return self.device.compiler.stats.compiles

    def post(self, event: Event) -> None:
        """Host input into the device's input controller (stamped with the device time; in
        the recording, if any)."""
        queued = self.device.post_event(event)
        if self._recorder is not None:
            self._recorder.record_input(queued)

    # ------------------------------------------------------------------ scenes
    def load_scene(self, path: str | Path) -> None:
        """Build a scene file's pad graph (``rainbow render``'s JSON) on this machine's
        device. Raises SceneError naming the file and where, or RainbowError when the
        device refuses what the scene asks (video memory, the graph's rules)."""
        load_scene(path, self.device)

    def reference(self) -> np.ndarray:
        """The screen by the per-pixel reference compositor (no band structure): the
        check of ``frame``."""
        return self.device.reference()

    def bands_text(self) -> str:
        """The band structure the video processor interprets, as text (compiled now)."""
        return self.device.bands().to_text()

    def replay(self, rec: Recording) -> ReplayResult:
        """A recording's commands and input played on this machine; the result lists every
        reply that differs from the recorded one."""
        return replay(rec, self.executor.handle, self.device.post_event)

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

    # ------------------------------------------------------------------ a socket
    @staticmethod
    def listen(port: int = 0) -> socket.socket:
        """A listening socket on 127.0.0.1:``port`` (0: any free port) for ``serve``; an
        OSError when the port cannot be had."""
        return listen(port)

    def serve(self, sock: socket.socket, connections: int | None = None,
              **limits: float) -> ServerStats:
        """Serve programs on ``sock`` (``listen``) one at a
        time, each a fresh pad-library session on this Rainbow, until ``connections`` have
        been served (None: for ever); ``limits``: frame_timeout, idle_timeout,
        session_time, poll (seconds)."""
        return serve(self.executor, sock, connections, **limits)

    # ------------------------------------------------------------------ a program's run
    def session_state(self) -> bytes:
        """The Rainbow as a program's saved run keeps it (harness/rainbow.py): the device's
        parts and the client's ids and calls, not the byte stream (the client sends whole
        frames)."""
        head, blobs = self.device.save_state()
        head["client"] = list(self.client.ids())
        return pack("rainbow-session", head, blobs)

    def check_session_state(self, data: bytes) -> Callable[[], None]:
        """MachineStateError unless ``data`` (session_state()) loads: it is loaded into a
        scratch device first; returns what puts it into this machine."""
        head, blobs = unpack(data, "rainbow-session")
        try:
            Rainbow(strict=self.strict_memory).load_state(head, blobs)
            client = head["client"]
            if not (isinstance(client, list) and len(client) == 3 and
                    all(type(v) is int and 0 <= v < 1 << 31 for v in client)):
                raise ValueError(f"client ids {str(client)[:40]} are damaged")
        except (ValueError, KeyError, TypeError, IndexError, RainbowError) as exc:
            raise MachineStateError(f"Rainbow state: {str(exc)[:200]}") from None

        def put() -> None:
            self.device.load_state(head, blobs)
            self.client.continue_from(tuple(client))
            self.executor.restart()  # the next frame composed again from the device
        return put
