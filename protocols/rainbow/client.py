"""The Rainbow pad library as a Python client API.

Every call becomes one frame of the command stream (stream.py) sent through a transport;
a refused call raises ``RainbowRefused`` with the device's message. Node and arc ids are
plain ints chosen here; ``SCREEN`` (0) is the root cluster, 768 x 576.
"""

from __future__ import annotations

import struct
from collections.abc import Iterable, Iterator, Sequence

import numpy as np

from camlab88.protocols.rainbow.events import Event, decode_events
from camlab88.protocols.rainbow.stream import OK, encode, split_reply
from camlab88.protocols.rainbow.transport import Transport

SCREEN = 0
SCREEN_W, SCREEN_H = 768, 576
LUT_SIZE = 4096

Colour = tuple[int, int, int] | str


class RainbowRefused(Exception):
    """The device refused a call (bad argument, out of video memory, cycle, ...)."""


def parse_colour(c: Colour) -> tuple[int, int, int]:
    """(r, g, b) or "#rrggbb" -> (r, g, b)."""
    if isinstance(c, str):
        s = c.strip()
        if len(s) != 7 or s[0] != "#":
            raise ValueError(f"colour {c!r} is not #rrggbb")
        try:
            return int(s[1:3], 16), int(s[3:5], 16), int(s[5:7], 16)
        except ValueError:
            raise ValueError(f"colour {c!r} is not #rrggbb") from None
    r, g, b = (int(v) for v in c)
    if not all(0 <= v <= 255 for v in (r, g, b)):
        raise ValueError(f"colour {c!r} has a component outside 0..255")
    return r, g, b


class RainbowClient:
    def __init__(self, transport: Transport) -> None:
        self.transport = transport
        self._next_node = 1
        self._next_arc = 1
        self.calls = 0

    # -- plumbing ----------------------------------------------------------------------------
    def _call(self, name: str, *args: int, blob: bytes = b"") -> bytes:
        self.calls += 1
        status, payload, _ = split_reply(self.transport.call(encode(name, *args, blob=blob)))
        if status != OK:
            raise RainbowRefused(f"{name}: {payload.decode(errors='replace')}")
        return payload

    def _node(self) -> int:
        n = self._next_node
        self._next_node += 1
        return n

    def close(self) -> None:
        self.transport.close()

    # -- saved with a machine ----------------------------------------------------------------
    def ids(self) -> tuple[int, int, int]:
        """(next node, next arc, calls made): what a saved session needs to go on naming
        nodes and arcs as the device expects."""
        return self._next_node, self._next_arc, self.calls

    def continue_from(self, ids: tuple[int, int, int]) -> None:
        """Go on from ``ids()``'s values (a machine's state being loaded)."""
        self._next_node, self._next_arc, self.calls = ids

    def hello(self) -> dict[str, int]:
        vals = struct.unpack("<5i", self._call("hello"))
        return dict(zip(("screen_w", "screen_h", "lut_size", "memory_w", "memory_h"), vals))

    # -- graph -------------------------------------------------------------------------------
    def create_pad(self, width: int, height: int, depth: int, plane: int = 0,
                   lut_page: int = 0) -> int:
        n = self._node()
        self._call("create_pad", n, width, height, depth, plane, lut_page)
        return n

    def create_cluster(self, width: int, height: int) -> int:
        n = self._node()
        self._call("create_cluster", n, width, height)
        return n

    def destroy(self, node: int) -> None:
        self._call("destroy", node)

    def map(self, parent: int, child: int, x: int = 0, y: int = 0, priority: int = 0,
            on: bool = True) -> int:
        a = self._next_arc
        self._next_arc += 1
        self._call("map", a, parent, child, x, y, priority, int(on))
        return a

    def unmap(self, arc: int) -> None:
        self._call("unmap", arc)

    def move(self, arc: int, x: int, y: int) -> None:
        self._call("move", arc, x, y)

    def set_priority(self, arc: int, priority: int) -> None:
        self._call("set_priority", arc, priority)

    def set_on(self, arc: int, on: bool) -> None:
        self._call("set_on", arc, int(on))

    def resize(self, cluster: int, width: int, height: int) -> None:
        self._call("resize", cluster, width, height)

    def set_page(self, pad: int, lut_page: int) -> None:
        self._call("set_page", pad, lut_page)

    # -- lookup table ------------------------------------------------------------------------
    def set_lut(self, start: int, colours: Iterable[Colour]) -> None:
        """Entries start, start+1, ...; they take effect at the next frame."""
        rgb = bytes(v for c in colours for v in parse_colour(c))
        self._call("set_lut", start, blob=rgb)

    # -- drawing -----------------------------------------------------------------------------
    def clear(self, pad: int, value: int = 0) -> None:
        self._call("clear", pad, value)

    def point(self, pad: int, x: int, y: int, value: int) -> None:
        self._call("point", pad, x, y, value)

    def line(self, pad: int, x0: int, y0: int, x1: int, y1: int, value: int) -> None:
        self._call("line", pad, x0, y0, x1, y1, value)

    def rect(self, pad: int, x: int, y: int, w: int, h: int, value: int,
             filled: bool = True) -> None:
        self._call("rect", pad, x, y, w, h, value, int(filled))

    def polygon(self, pad: int, points: Sequence[tuple[int, int]], value: int) -> None:
        blob = struct.pack(f"<{2 * len(points)}i", *(int(v) for p in points for v in p))
        self._call("polygon", pad, value, blob=blob)

    def circle(self, pad: int, cx: int, cy: int, r: int, value: int) -> None:
        """A filled disc (the fast circle routine of §6.3.2)."""
        self._call("circle", pad, cx, cy, r, value)

    def text(self, pad: int, x: int, y: int, s: str, value: int, scale: int = 1) -> None:
        """Ink pixels only, 6 x 10 cells (x scale), top-left at (x, y)."""
        self._call("text", pad, x, y, value, scale, blob=s.encode())

    def put_pixels(self, pad: int, x: int, y: int, values: np.ndarray) -> None:
        a = np.asarray(values)
        if a.ndim != 2 or (a.size and (a.min() < 0 or a.max() > 255)):
            raise ValueError("put_pixels wants a 2-D array of values 0..255")
        h, w = a.shape
        self._call("put_pixels", pad, x, y, w, h, blob=a.astype(np.uint8).tobytes())

    def get_pixels(self, pad: int, x: int, y: int, w: int, h: int) -> np.ndarray:
        data = self._call("get_pixels", pad, x, y, w, h)
        return np.frombuffer(data, np.uint8).reshape(h, w).copy()

    def copy(self, src: int, sx: int, sy: int, w: int, h: int, dst: int, dx: int,
             dy: int) -> None:
        self._call("copy", src, sx, sy, w, h, dst, dx, dy)

    # -- time and input ----------------------------------------------------------------------
    def poll_events(self, limit: int = 256) -> list[Event]:
        return decode_events(self._call("poll_events", limit), "poll_events reply")

    def drain_events(self, limit: int = 256) -> Iterator[Event]:
        """Every queued input event in order, however many arrived since the last look: a
        reply that comes back full (``limit`` events) means more wait, so poll again."""
        while True:
            events = self.poll_events(limit)
            yield from events
            if len(events) < limit:
                return

    def wait_frame(self) -> tuple[int, int]:
        """Let the device show one frame (50 Hz); returns (frame count, device time ms)."""
        frame, t = struct.unpack("<qq", self._call("wait_frame"))
        return frame, t
