"""The device end of the command stream: decode a frame, carry it out, answer it.

A refused or malformed command is answered with an error reply and leaves the device as
it was; nothing a program sends can crash the emulator.
"""

from __future__ import annotations

import struct
from collections.abc import Callable

import numpy as np

from camlab88.emulator.rainbow.device import Rainbow
from camlab88.emulator.rainbow.errors import RainbowError
from camlab88.emulator.rainbow.graph import SCREEN_H, SCREEN_W
from camlab88.emulator.rainbow.trace import RainbowTracer
from camlab88.emulator.rainbow.video import LUT_SIZE
from camlab88.protocols.rainbow.events import encode_event
from camlab88.protocols.rainbow.stream import (
    OK,
    REFUSED,
    Command,
    Decoder,
    StreamError,
    encode_reply,
)


class Executor:
    def __init__(self, device: Rainbow,
                 on_frame: Callable[[np.ndarray], None] | None = None) -> None:
        self.device = device
        self.on_frame = on_frame  # the window shows frames and feeds host input here
        self.decoder = Decoder()
        # The most recent frame, or None before the first wait_frame. It is ONE buffer that
        # every later frame is composed into (no allocation per frame), so it changes under
        # whoever holds it: keep frame_copy() if a frame must survive the next wait_frame.
        self.last_frame: np.ndarray | None = None
        self.tracer: RainbowTracer | None = None  # protocol trace (emulator/rainbow/trace.py)

    def restart(self) -> None:
        """Forget the stream's unfinished frame and the last frame (the device's state was
        loaded from a file: the next frame is composed from it)."""
        self.decoder = Decoder()
        self.last_frame = None

    def frame_copy(self) -> np.ndarray | None:
        """A copy of the last frame that later frames will not overwrite (None before one)."""
        return None if self.last_frame is None else self.last_frame.copy()

    def handle(self, frame: bytes) -> bytes:
        """One command frame in, one reply frame out (the in-process transport)."""
        decoder = Decoder()
        try:
            cmds = decoder.feed(frame)
            if len(cmds) != 1 or decoder.pending:
                raise StreamError("byte 0: expected exactly one whole command frame")
        except StreamError as exc:
            if self.tracer is not None:
                self.tracer.stream_error(exc, self.device.time_ms, frame[:12])
            return encode_reply(REFUSED, str(exc).encode())
        return self.execute(cmds[0])

    def feed(self, data: bytes) -> bytes:
        """Bytes from a stream (split anywhere) -> replies for every whole command in them."""
        if self.tracer is None:
            return b"".join(self.execute(c) for c in self.decoder.feed(data))
        try:
            cmds = self.decoder.feed(data)
        except StreamError as exc:
            self.tracer.stream_error(exc, self.device.time_ms, data[:12])
            raise
        replies = b"".join(self.execute(c) for c in cmds)
        if self.decoder.error is not None:
            self.tracer.stream_error(self.decoder.error, self.device.time_ms)
        return replies

    def execute(self, cmd: Command) -> bytes:
        try:
            payload = getattr(self, "_op_" + cmd.op.name)(*cmd.args, blob=cmd.blob)
        except (RainbowError, ValueError) as exc:
            reply = encode_reply(REFUSED, f"{cmd.op.name} at byte {cmd.offset}: {exc}".encode())
        else:
            reply = encode_reply(OK, payload or b"")
        if self.tracer is not None:
            self.tracer.command(cmd, reply, self.device.time_ms)
        return reply

    # -- one method per op ---------------------------------------------------------------
    def _op_hello(self, blob: bytes) -> bytes:
        m = self.device.memory
        return struct.pack("<5i", SCREEN_W, SCREEN_H, LUT_SIZE, m.width, m.height)

    def _op_create_pad(self, node, w, h, depth, plane, page, blob) -> None:
        self.device.create_pad(w, h, depth, plane, page, node=node)

    def _op_create_cluster(self, node, w, h, blob) -> None:
        self.device.create_cluster(w, h, node=node)

    def _op_destroy(self, node, blob) -> None:
        self.device.destroy(node)

    def _op_map(self, arc, parent, child, x, y, prio, on, blob) -> None:
        self.device.map(parent, child, x, y, prio, bool(on), arc=arc)

    def _op_unmap(self, arc, blob) -> None:
        self.device.unmap(arc)

    def _op_move(self, arc, x, y, blob) -> None:
        self.device.move(arc, x, y)

    def _op_set_priority(self, arc, prio, blob) -> None:
        self.device.set_priority(arc, prio)

    def _op_set_on(self, arc, on, blob) -> None:
        self.device.set_on(arc, bool(on))

    def _op_resize(self, node, w, h, blob) -> None:
        self.device.resize(node, w, h)

    def _op_set_page(self, node, page, blob) -> None:
        self.device.set_page(node, page)

    def _op_set_lut(self, start, blob) -> None:
        if len(blob) % 3:
            raise RainbowError(f"set_lut blob of {len(blob)} bytes is not whole RGB triples")
        self.device.set_lut(start, np.frombuffer(blob, np.uint8).reshape(-1, 3))

    def _op_clear(self, node, value, blob) -> None:
        self.device.canvas(node).clear(value)

    def _op_point(self, node, x, y, value, blob) -> None:
        self.device.canvas(node).point(x, y, value)

    def _op_line(self, node, x0, y0, x1, y1, value, blob) -> None:
        self.device.canvas(node).line(x0, y0, x1, y1, value)

    def _op_rect(self, node, x, y, w, h, value, filled, blob) -> None:
        self.device.canvas(node).rect(x, y, w, h, value, bool(filled))

    def _op_polygon(self, node, value, blob) -> None:
        if len(blob) % 8:
            raise RainbowError(f"polygon blob of {len(blob)} bytes is not whole x, y pairs")
        pts = np.frombuffer(blob, "<i4").reshape(-1, 2).tolist()
        self.device.canvas(node).polygon([tuple(p) for p in pts], value)

    def _op_circle(self, node, cx, cy, r, value, blob) -> None:
        self.device.canvas(node).circle(cx, cy, r, value)

    def _op_text(self, node, x, y, value, scale, blob) -> None:
        try:
            s = blob.decode()
        except UnicodeDecodeError as exc:
            raise RainbowError(f"text is not UTF-8 ({exc})") from None
        self.device.canvas(node).text(x, y, s, value, scale)

    def _op_put_pixels(self, node, x, y, w, h, blob) -> None:
        if w < 0 or h < 0 or len(blob) != w * h:
            raise RainbowError(f"put_pixels: {len(blob)} bytes for a {w}x{h} block")
        self.device.canvas(node).put(x, y, np.frombuffer(blob, np.uint8).reshape(h, w))

    def _op_get_pixels(self, node, x, y, w, h, blob) -> bytes:
        return self.device.canvas(node).read(x, y, w, h).astype(np.uint8).tobytes()

    def _op_copy(self, src, sx, sy, w, h, dst, dx, dy, blob) -> None:
        self.device.copy(src, sx, sy, w, h, dst, dx, dy)

    def _op_poll_events(self, limit, blob) -> bytes:
        return b"".join(encode_event(e) for e in self.device.take_events(max(limit, 0)))

    def _op_wait_frame(self, blob) -> bytes:
        self.last_frame = self.device.frame(self.last_frame)
        if self.on_frame is not None:
            self.on_frame(self.last_frame)
        return struct.pack("<qq", self.device.frame_count, self.device.time_ms)
