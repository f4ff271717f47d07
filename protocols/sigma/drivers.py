"""Streams formed the way the two public host drivers formed them (facts/sigma.md S1, S2, S3).

``PgplotGoc`` is PGPLOT's GOC driver (godriv.f) byte for byte on the calls of the real
streams in tests/data/sigma/pgplot: the init string CR LF ``+-*/DD000CBGAAAHE999CK1GH BH``,
buffers ``+-*/GJ ... BH`` flushed once within 32 bytes of 130, NGS decimal pairs with +100,
FA/FB colours, the alpha erase ``+-*/GJ BH FF +-*/ BH``, the cursor prompt
``+-*/GICECA xxxyyy CFHF`` and its 11-byte trailer ``+-*/CECBGJB``.

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

from camlab88.protocols.sigma.abbreviated import AgsPointEncoder
from camlab88.protocols.sigma.encoder import Encoder
from camlab88.protocols.sigma.orders import CR, GRAPHICS_FLAG, LF, US


class PgplotGoc:
    """PGPLOT /GOC (T5670-style, 768x512, colour indices 0 and 1), byte for byte as
    PGPLOT 5.2.2's godriv.f forms its stream (checked against the driver's real output,
    tests/sigma/test_pgplot.py).

    Every buffer opens with ``+-*/GJ`` and closes with ``BH``; it is flushed once it holds
    ``BUFFER_BYTES - FLUSH_WITHIN`` = 98 bytes or more (GRGO02), or when PGPLOT asks. A line
    whose start is not where the last one ended is ``GI xxxyyy GJ xxxyyy``, else one bare
    pair; the last point is remembered across buffers, pages and cursor reads.
    """

    BUFFER_BYTES = 130
    FLUSH_WITHIN = 32
    INIT = b"DD000CBGAAAHE999CK1GH"
    ERASE_ALPHA = b"BH\x0c" + GRAPHICS_FLAG  # GOCERA, sent as one buffer's contents
    CURSOR_END = GRAPHICS_FLAG + b"CECBGJB"  # GCEND*11: the last H of +-*/CECBGJBH is lost

    def __init__(self) -> None:
        self.enc = Encoder()
        self.out = bytearray()
        self._buf = bytearray()
        self._last: tuple[int, int] | None = None  # where a bare pair continues from

    def _put(self, data: bytes) -> None:
        if not self._buf:
            self._buf += GRAPHICS_FLAG + b"GJ"
        self._buf += data
        if self.BUFFER_BYTES - len(self._buf) <= self.FLUSH_WITHIN:
            self.flush()

    def flush(self) -> None:
        """GRGO03: send the buffer with BH appended (nothing if it is empty)."""
        if self._buf:
            self.out += self._buf + b"BH"
            self._buf = bytearray()

    def init(self) -> None:
        """GRGO10: CR LF, the flag, the initialisation orders, BH (not buffered)."""
        self.flush()
        self.out += bytes((CR, LF)) + GRAPHICS_FLAG + self.INIT + b"BH"

    def begin_picture(self) -> None:
        """IFUNC 11: initialise, then erase the graphics (DA, buffered)."""
        self.init()
        self.erase()

    def erase(self) -> None:
        self._put(self.enc.erase())

    def colour(self, ci: int) -> None:
        self._put(self.enc.pen_draw() if ci >= 1 else self.enc.pen_erase())

    def line(self, x0: int, y0: int, x1: int, y1: int) -> None:
        if self._last == (x0, y0):
            self._put(self.enc.pair(x1, y1))
        else:
            self._put(self.enc.pen_up() + self.enc.pair(x0, y0) + self.enc.pen_down()
                      + self.enc.pair(x1, y1))
        self._last = (x1, y1)

    def polyline(self, points: Sequence[tuple[int, int]]) -> None:
        for (x0, y0), (x1, y1) in zip(points, points[1:]):
            self.line(x0, y0, x1, y1)

    def dot(self, x: int, y: int) -> None:
        self.line(x, y, x, y)

    def frame(self, x0: int, y0: int, x1: int, y1: int, xticks: int, yticks: int = 0,
              tick: int = 12) -> None:
        """A graph's frame as a PGPLOT program draws it (PGBOX's lines): the rectangle,
        then ``xticks`` evenly spaced ticks ``tick`` long into it from the bottom and top
        edges, then ``yticks`` from the left edge."""
        self.polyline([(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)])
        for k in range(xticks):
            x = x0 + (x1 - x0) * k // (xticks - 1)
            self.line(x, y0, x, y0 + tick)
            self.line(x, y1, x, y1 - tick)
        for k in range(yticks):
            y = y0 + (y1 - y0) * k // (yticks - 1)
            self.line(x0, y, x0 + tick, y)

    def cursor_prompt(self, x: int, y: int) -> bytes:
        """GRGO11's read-with-prompt: flush, then flag GI CE CA xxxyyy CF HF (returned,
        and added to the stream)."""
        self.flush()
        prompt = GRAPHICS_FLAG + b"GICECA" + self.enc.pair(x, y) + b"CFHF"
        self.out += prompt
        return prompt

    def after_cursor(self) -> None:
        """GRGO11's trailer, as the driver really sends it: 11 of its 12 bytes, leaving the
        terminal in graphics mode with a stray B (docs/fidelity/sigma.md)."""
        self.out += self.CURSOR_END

    def erase_alpha(self) -> None:
        """IFUNC 18: flush, BH FF +-*/ as one buffer (so +-*/GJ BH FF +-*/ BH), flush."""
        self.flush()
        self._put(self.ERASE_ALPHA)
        self.flush()

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

    def message(self, text: str) -> None:
        self._put(b"AABH")
        self._buf += text.encode("ascii")
        self.flush()

    def finish(self) -> bytes:
        self.flush()
        return bytes(self.out)
