"""Protocol traces for the Rainbow's command stream: every command with its stream offset,
the device time, the op's name and decoded fields, and the device's refusal as a warning.

The executor calls ``command`` after each command and ``stream_error`` when a frame cannot be
decoded; ``strict`` raises ``ProtocolError`` at the first refusal or bad frame.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from camlab88.emulator.protocol_trace import ProtocolError, TraceEvent
from camlab88.protocols.rainbow.stream import HEADER, OK, Command, StreamError, split_reply

__all__ = ["ProtocolError", "RainbowTracer", "TraceEvent"]


def _expected(cmd: Command) -> str:
    op = cmd.op
    blob = f" then {op.blob}" if op.blob else ""
    return f"{op.name}({', '.join(op.fields)}){blob} with values the device accepts"


class RainbowTracer:
    """Reports each command of a stream to ``sink``."""

    def __init__(self, sink: Callable[[TraceEvent], None], strict: bool = False) -> None:
        self.sink, self.strict = sink, strict
        self.warnings = 0
        self.position = 0  # stream offset of the next command (in-process calls included)

    def command(self, cmd: Command, reply: bytes, time_ms: int) -> None:
        args: dict[str, Any] = dict(zip(cmd.op.fields, cmd.args))
        if cmd.blob:
            args["blob_bytes"] = len(cmd.blob)
        status, payload, _ = split_reply(reply)
        ev = TraceEvent(self.position, time_ms / 1000, cmd.op.name, args)
        self.position += HEADER.size + 4 * len(cmd.args) + len(cmd.blob)
        if status != OK:
            ev.warning = payload.decode("utf-8", "replace")
            ev.kind, ev.expected = "refused", _expected(cmd)
        self._emit(ev)

    def stream_error(self, error: StreamError, time_ms: int, context: bytes = b"") -> None:
        text = str(error)
        offset = int(text.split()[1].rstrip(":")) if text.startswith("byte ") else 0
        self._emit(TraceEvent(offset, time_ms / 1000, "bad frame", {}, text, "malformed",
                              "u8 opcode 1-24, u32 payload length, the op's int32 fields",
                              context))

    def _emit(self, ev: TraceEvent) -> None:
        self.sink(ev)
        if ev.warning is not None:
            self.warnings += 1
            if self.strict:
                raise ProtocolError(ev)
