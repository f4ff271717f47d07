"""The Rainbow command stream: every pad-library call as one binary frame.

One table (``OPS``) serves the client's encoder and the device's decoder, so the two cannot
drift apart. Frame layout (little-endian)::

    u8  opcode
    u32 payload length in bytes
    payload: the op's int32 fields in table order, then (for ops with a blob) the blob

Every command is answered by a reply frame::

    u8  status   (0 = done, 1 = refused: the payload is a UTF-8 error message)
    u32 payload length
    payload      (op-specific result, e.g. pixel bytes or encoded events; often empty)

Node and arc ids are chosen by the client (0 is the screen), so building a scene needs no
round trip for ids; the device refuses an id already in use.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass

HEADER = struct.Struct("<BI")
MAX_PAYLOAD = 16 << 20  # a full 8-bit 2048x2048 pixel block fits; more is a broken stream

OK, REFUSED = 0, 1


@dataclass(frozen=True)
class Op:
    code: int
    name: str
    fields: tuple[str, ...]
    blob: str | None = None  # meaning of the trailing bytes, if any
    reply: str | None = None  # meaning of the reply payload, if any


OPS_LIST: tuple[Op, ...] = (
    Op(1, "create_pad", ("node", "width", "height", "depth", "plane", "lut_page")),
    Op(2, "create_cluster", ("node", "width", "height")),
    Op(3, "destroy", ("node",)),
    Op(4, "map", ("arc", "parent", "child", "x", "y", "priority", "on")),
    Op(5, "unmap", ("arc",)),
    Op(6, "move", ("arc", "x", "y")),
    Op(7, "set_priority", ("arc", "priority")),
    Op(8, "set_on", ("arc", "on")),
    Op(9, "resize", ("node", "width", "height")),
    Op(10, "set_page", ("node", "lut_page")),
    Op(11, "set_lut", ("start",), blob="rgb bytes, 3 per entry"),
    Op(12, "clear", ("node", "value")),
    Op(13, "point", ("node", "x", "y", "value")),
    Op(14, "line", ("node", "x0", "y0", "x1", "y1", "value")),
    Op(15, "rect", ("node", "x", "y", "w", "h", "value", "filled")),
    Op(16, "polygon", ("node", "value"), blob="int32 x, y pairs"),
    Op(17, "circle", ("node", "cx", "cy", "r", "value")),
    Op(18, "text", ("node", "x", "y", "value", "scale"), blob="UTF-8 text"),
    Op(19, "put_pixels", ("node", "x", "y", "w", "h"), blob="w*h bytes, row-major"),
    Op(20, "get_pixels", ("node", "x", "y", "w", "h"), reply="w*h bytes, row-major"),
    Op(21, "copy", ("src", "sx", "sy", "w", "h", "dst", "dx", "dy")),
    Op(22, "poll_events", ("limit",), reply="encoded events (protocols.rainbow.events)"),
    Op(23, "wait_frame", (), reply="int64 frame count, int64 device time in ms"),
    Op(24, "hello", (), reply="int32 screen width, height, lut size, memory width, height"),
)
OPS = {op.name: op for op in OPS_LIST}
BY_CODE = {op.code: op for op in OPS_LIST}


class StreamError(ValueError):
    """A malformed frame; the message names the byte offset in the stream."""


@dataclass(frozen=True)
class Command:
    op: Op
    args: tuple[int, ...]
    blob: bytes = b""
    offset: int = 0  # byte offset of the frame in its stream (for error messages)


def encode(name: str, *args: int, blob: bytes = b"") -> bytes:
    op = OPS[name]
    if len(args) != len(op.fields):
        raise TypeError(f"{name} takes {op.fields}, got {len(args)} values")
    if blob and op.blob is None:
        raise TypeError(f"{name} carries no blob")
    try:
        body = struct.pack(f"<{len(args)}i", *(int(a) for a in args)) + blob
    except struct.error as exc:
        raise ValueError(f"{name}: an argument is outside int32 ({exc})") from None
    return HEADER.pack(op.code, len(body)) + body


def encode_reply(status: int, payload: bytes = b"") -> bytes:
    return HEADER.pack(status, len(payload)) + payload


class Decoder:
    """Incremental: feed bytes split anywhere, take whole commands out.

    A malformed frame cannot be skipped (its length may be garbage), so the decoder stops
    there: the whole commands before it are returned, ``error`` is set, and every later
    ``feed`` raises it.
    """

    def __init__(self) -> None:
        self._buf = bytearray()
        self._offset = 0  # stream offset of _buf[0]
        self.error: StreamError | None = None

    def feed(self, data: bytes) -> list[Command]:
        if self.error is not None:
            raise self.error
        self._buf += data
        out = []
        while len(self._buf) >= HEADER.size:
            code, n = HEADER.unpack_from(self._buf)
            at = self._offset
            op = BY_CODE.get(code)
            if op is None:
                self.error = StreamError(f"byte {at}: unknown opcode {code}")
                break
            if n > MAX_PAYLOAD:
                self.error = StreamError(f"byte {at}: {op.name} payload of {n} bytes is too long")
                break
            if len(self._buf) < HEADER.size + n:
                break
            body = bytes(self._buf[HEADER.size: HEADER.size + n])
            need = 4 * len(op.fields)
            if n < need or (op.blob is None and n != need):
                self.error = StreamError(
                    f"byte {at}: {op.name} payload is {n} bytes, expected "
                    f"{need}{' or more' if op.blob else ''}"
                )
                break
            args = struct.unpack_from(f"<{len(op.fields)}i", body)
            out.append(Command(op, args, body[need:], at))
            del self._buf[: HEADER.size + n]
            self._offset += HEADER.size + n
        if self.error is not None and not out:
            raise self.error
        return out

    @property
    def pending(self) -> int:
        return len(self._buf)

    @property
    def at(self) -> int:
        """Stream offset of the first byte not yet part of a whole frame (the unfinished
        frame's start): it moves whenever a frame is completed."""
        return self._offset

    def position(self) -> tuple[int, bytes]:
        """(offset, the unfinished frame's bytes): where a saved stream stands."""
        return self._offset, bytes(self._buf)

    def resume(self, offset: int, pending: bytes) -> None:
        """Stand where ``position()`` said (a machine's state being loaded)."""
        self._offset, self._buf = offset, bytearray(pending)


def split_reply(data: bytes) -> tuple[int, bytes, bytes]:
    """(status, payload, rest) from the front of ``data``; raises if it is incomplete."""
    if len(data) < HEADER.size:
        raise StreamError("reply truncated in its header")
    status, n = HEADER.unpack_from(data)
    if len(data) < HEADER.size + n:
        raise StreamError("reply truncated in its payload")
    return status, data[HEADER.size: HEADER.size + n], data[HEADER.size + n:]
