"""Streams formed the way the two public host drivers formed them (facts/sigma.md S1, S2, S3).

``PgplotGoc`` follows PGPLOT's GOC driver (godriv.f): the init string CR LF ``+-*/``
``DD000CBGAAAHE999CK1GH``, buffers of at most 130 bytes flushed when fewer than 32 are left,
each buffer opened with the graphics flag and closed with ``BH``; NGS decimal pairs with
+100; FA/FB colours; the cursor prompt ``GI CE CA xxxyyy CF HF``.

``RalGks`` follows the RAL GKS Sigmex driver (gk0swd/gk0sln/gk0sro/gk0srl): every buffer is
CR ``+-*/`` ... CR LF; open sends HH + 10 NULs, DD000, DG017DF019, GA, AJ, CK1, GH (and IO on
high-resolution models) and a JG per colour; polylines in abbreviated mode with repeated
points dropped (a 2-point zero-length line kept to make a dot) and long ones split with the
last point repeated; cell arrays as a 1-point AGS move then DJ runs, Z before each flush.

Where the facts leave a detail open (the exact order of the open sequence, the GKS buffer
size, when PGPLOT re-sends GI/GJ) the choice is ours and is listed in docs/fidelity/sigma.md.
"""

from __future__ import annotations

from collections.abc import Sequence

from protocols.sigma.abbreviated import AgsPointEncoder
from protocols.sigma.encoder import Encoder
from protocols.sigma.orders import CR, GRAPHICS_FLAG, LF, US


class PgplotGoc:
    """PGPLOT /GOC (T5670-style, 768x512, colour indices 0 and 1)."""

    BUFFER_BYTES = 130
    FLUSH_BELOW = 32

    def __init__(self) -> None:
        self.enc = Encoder()
        self.out = bytearray()
        self._buf = bytearray()
        self._pen: tuple[int, int] | None = None  # where a bare pair would continue from

    def _put(self, data: bytes) -> None:
        if not self._buf:
            self._buf += GRAPHICS_FLAG
            self._pen = None  # a new buffer re-states the pen mode
        self._buf += data
        if self.BUFFER_BYTES - len(self._buf) < self.FLUSH_BELOW:
            self.flush()

    def flush(self) -> None:
        if self._buf:
            self.out += self._buf + b"BH"
            self._buf = bytearray()
            self._pen = None

    def init(self) -> None:
        self.flush()
        self.out += bytes((CR, LF)) + GRAPHICS_FLAG + b"DD000CBGAAAHE999CK1GH" + b"BH"

    def erase(self) -> None:
        self._put(self.enc.erase())

    def colour(self, ci: int) -> None:
        self._put(self.enc.pen_draw() if ci >= 1 else self.enc.pen_erase())

    def line(self, x0: int, y0: int, x1: int, y1: int) -> None:
        if self._pen == (x0, y0):
            self._put(self.enc.pair(x1, y1))
        else:
            self._put(self.enc.move(x0, y0) + self.enc.draw(x1, y1))
        self._pen = (x1, y1)

    def polyline(self, points: Sequence[tuple[int, int]]) -> None:
        for (x0, y0), (x1, y1) in zip(points, points[1:]):
            self.line(x0, y0, x1, y1)

    def dot(self, x: int, y: int) -> None:
        self.line(x, y, x, y)

    def cursor_prompt(self, x: int, y: int) -> bytes:
        """The read-with-prompt bytes: flag GI CE CA xxxyyy CF HF."""
        self.flush()
        return GRAPHICS_FLAG + b"GICECA" + self.enc.pair(x, y) + b"CFHF"

    def after_cursor(self) -> None:
        self.flush()
        self.out += GRAPHICS_FLAG + b"CECBGJBH"

    def erase_alpha(self) -> None:
        self.flush()
        self.out += b"BH\x0c" + GRAPHICS_FLAG + b"BH"

    def finish(self) -> bytes:
        self.flush()
        return bytes(self.out)


class RalGks:
    """RAL GKS Sigmex driver, B series (5684 = type 106, 5688 = types 107/108)."""

    BUFFER_BYTES = 200  # the real size is not in the facts: reconstructed
    DASHES = {1: None, 2: 0xF0F0, 3: 0x8888, 4: 0xFE10, 5: 0xF888}  # GKS linetype -> DL mask

    def __init__(self, high_res: bool = False) -> None:
        self.high_res = high_res
        self.enc = Encoder(high_res=high_res)
        self.out = bytearray()
        self._buf = bytearray()
        self._dots_open = False

    # ---- buffer framing (IBEGB / IENDB / KIOSO)
    def _room(self, n: int) -> bool:
        return len(self._buf) + n + 2 <= self.BUFFER_BYTES

    def _put(self, data: bytes) -> None:
        if self._buf and not self._room(len(data)):
            self.flush()
        if not self._buf:
            self._buf += bytes((CR,)) + GRAPHICS_FLAG
        self._buf += data

    def flush(self, trailer: bool = True) -> None:
        if self._dots_open:
            self._buf += b"Z"
            self._dots_open = False
        if self._buf:
            self.out += self._buf + (bytes((CR, LF)) if trailer else b"")
            self._buf = bytearray()

    # ---- workstation
    def open(self, colours: Sequence[tuple[float, float, float]]) -> None:
        self._put(self.enc.reset())
        self._put(self.enc.flag_anywhere())
        self._put(self.enc.sequence_length(0) + self.enc.xon_char(17) + self.enc.xoff_char(19))
        self._put(self.enc.graphics_on() + self.enc.alpha_off() + self.enc.cursor_shape(1))
        if self.high_res:
            self._put(self.enc.coords4())
        for i, (r, g, b) in enumerate(colours[:16]):
            self.set_colour_representation(i, r, g, b)
        self._put(self.enc.cursor_off() + b"FGFC")
        self.flush()

    def set_colour_representation(self, i: int, r: float, g: float, b: float) -> None:
        self._put(self.enc.lut(i, round(15 * r), round(15 * g), round(15 * b)))

    def clear(self) -> None:
        self._put(self.enc.erase())

    def colour(self, ci: int) -> None:
        self._put(self.enc.colour(ci))

    def linetype(self, lt: int) -> None:
        mask = self.DASHES.get(lt)
        self._put(b"FGFC" if mask is None else self.enc.dash(mask))

    def polyline(self, points: Sequence[tuple[int, int]]) -> None:
        pts: list[tuple[int, int]] = []
        for p in points:
            if not pts or p != pts[-1]:
                pts.append((int(p[0]), int(p[1])))
        if len(pts) == 1 and len(points) >= 2:
            pts.append(pts[0])  # a zero-length line is kept to make a dot
        if len(pts) < 2:
            return
        per_point = 5 if self.high_res else 4
        i = 0
        while i < len(pts) - 1:
            if self._buf and not self._room(2 + 2 * per_point + 1):
                self.flush()
            if not self._buf:
                self._buf += bytes((CR,)) + GRAPHICS_FLAG
            room = (self.BUFFER_BYTES - len(self._buf) - 2 - 3) // per_point
            chunk = pts[i:i + max(room, 2)]
            enc = AgsPointEncoder(self.high_res)
            self._buf += b"JH" + b"".join(enc.encode(x, y) for x, y in chunk) + bytes((US,))
            i += len(chunk) - 1  # the next run repeats the last point (it moves there)
            if i < len(pts) - 1:
                self.flush()

    def cell_row(self, x: int, y: int, colours: Sequence[int]) -> None:
        """GK0SRO: move to the row start with a 1-point AGS run, then DJ pixel digits."""
        self._put(self.enc.abbreviated_polyline([(x, y)]))
        for c in colours:
            if not self._dots_open:
                self._put(b"DJ")
                self._dots_open = True
            if not self._room(2):
                self.flush()
                self._put(b"DJ")
                self._dots_open = True
            self._buf += b"%X" % c
        if self._dots_open:
            self._buf += b"Z"
            self._dots_open = False

    def request_locator(self, x: int, y: int, tablet: bool = False, echo: bool = True) -> bytes:
        """Locator prompt: CE, AGS move, CF or GM3, 80 NULs, CA, flush without trailer, HF."""
        self._put(self.enc.cursor_attach())
        self._put(self.enc.abbreviated_polyline([(x, y)]))
        self._put(self.enc.cursor_device(3) if tablet else self.enc.cursor_joystick())
        self._put(bytes(80))
        if echo:
            self._put(self.enc.cursor_on())
        self.flush(trailer=False)
        self.out += b"HF"
        return bytes(self.out)

    def end_locator(self) -> None:
        self._put(self.enc.cursor_off())

    def message(self, text: str) -> None:
        self._put(b"AABH")
        self._buf += text.encode("ascii")
        self.flush()

    def finish(self) -> bytes:
        self.flush()
        return bytes(self.out)
