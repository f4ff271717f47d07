"""Device-side incremental decoder: bytes (split anywhere) -> typed commands.

It never raises on any input: unknown orders and stray bytes are skipped and counted, a
parameter interrupted by a non-digit is dropped (counted as malformed) and the interrupting
byte is decoded afresh, so the decoder resynchronises at the next order. Everything it holds
between feeds is bounded (a partial order, a partial AGS point, at most MAX_TEXT text bytes,
one held DJ letter) and can be saved and restored (get_state / set_state).
"""

from __future__ import annotations

import copy
import re
from collections.abc import Callable

import numpy as np

from camlab88.protocols.sigma import abbreviated
from camlab88.protocols.sigma.commands import (
    AgsEnd,
    AgsEscape,
    AgsPoints,
    AlphaText,
    Command,
    DecoderStats,
    Dots,
    DotsEnd,
    GraphicsFlag,
    GraphicsText,
    Order,
    Point,
    Points,
)
from camlab88.protocols.sigma.decoder_state import DecoderState
from camlab88.protocols.sigma.orders import (
    BY_CODE,
    CR,
    FF,
    FIRST_LETTERS,
    GRAPHICS_FLAG,
    LF,
    US,
    Kind,
    Mode,
    OrderSpec,
    digit_value,
)

_DIGITS = re.compile(rb"[0-9]+")
_TENS = np.array((1000, 100, 10, 1), dtype=np.int32)
_IGNORED_IN_GRAPHICS = frozenset({0x00, CR, LF, 0x11, 0x13, 0x20, 0x7F})

AgsScanner = Callable[[np.ndarray, int, np.ndarray, np.ndarray, int], tuple[int, int]]


class Decoder:
    """Feed bytes; get commands. ``coord_digits`` follows IO/IP, ``gh`` follows GH."""

    MAX_TEXT = 256

    def __init__(self, ags_scanner: AgsScanner = abbreviated.scan_points) -> None:
        self.stats = DecoderStats()
        # the AGS point loop; the emulator passes a numba-compiled copy of scan_points
        self.ags_scanner = ags_scanner
        self._buf: np.ndarray | None = None
        self._xy: np.ndarray | None = None
        self._k = 0
        self.power_on()

    def power_on(self) -> None:
        self.mode = Mode.ALPHA
        self.coord_digits = 3
        self.gh = False
        self._line_start = True
        self._clear_partial()

    def _clear_partial(self) -> None:
        self._flag_k = 0  # bytes of +-*/ matched so far
        self._letter = -1  # first letter of an order, or -1
        self._spec: OrderSpec | None = None  # order whose fields are being read
        self._field_i = 0
        self._digits_left = 0
        self._value = 0
        self._args: list[int] = []
        self._pair: list[int] = []  # digits of a bare coordinate pair
        self._ags_state = abbreviated.new_state()
        self._ags_first = True
        self._esc: list[int] | None = None  # ESC letter + params being read in AGS
        self._text = bytearray()
        self._text_over = False
        self._dots_hold = -1  # a last dot A-F held back: with the next letter it may be an order

    @property
    def mid_order(self) -> bool:
        """Whether part of an order has arrived and its rest has not: a graphics flag being
        matched, an order's letters or fields, a bare coordinate pair, an ESC sequence, or a
        graphics text (BA ... CR) not yet ended.  (AGS and dot modes between their points
        are modes, not unfinished orders.)"""
        if self.mode is Mode.TEXT:
            return True
        if self.mode is Mode.NGS and not self._idle():
            return True
        return bool(self._flag_k) or self._esc is not None

    def drop_partial(self) -> None:
        """Forget a half-received order (its sender has gone); modes and settings stay."""
        if self.mode is Mode.TEXT:
            self.mode = Mode.NGS
        self._clear_partial()

    # ------------------------------------------------------------------ state
    def get_state(self) -> dict[str, object]:
        """Everything the decoder holds between feeds, as JSON-able values (see set_state)."""
        return self.capture().to_json()

    def set_state(self, state: dict[str, object]) -> None:
        """Restore get_state()'s dict; ValueError naming the first bad or unknown entry
        (checked completely before anything changes)."""
        self.resume(DecoderState.from_json(state, self.MAX_TEXT))

    def capture(self) -> DecoderState:
        """The partial state as a value (the decoder's own fields, copied)."""
        return DecoderState(
            self.mode, self.coord_digits, self.gh, self._line_start, self._flag_k,
            self._letter, self._spec, self._field_i, self._digits_left, self._value,
            list(self._args), list(self._pair), [int(v) for v in self._ags_state],
            self._ags_first, None if self._esc is None else list(self._esc), bytes(self._text),
            self._text_over, self._dots_hold, copy.deepcopy(self.stats))

    def resume(self, st: DecoderState) -> None:
        """Continue from a captured (or restored) state."""
        self._clear_partial()
        self.mode, self.coord_digits, self.gh = st.mode, st.coord_digits, st.gh
        self._line_start, self._flag_k, self._letter = st.line_start, st.flag_k, st.letter
        self._spec, self._field_i, self._digits_left = st.spec, st.field_i, st.digits_left
        self._value, self._args, self._pair = st.value, list(st.args), list(st.pair)
        self._ags_state = np.array(st.ags, dtype=np.int32)
        self._ags_first = st.ags_first
        self._esc = None if st.esc is None else list(st.esc)
        self._text, self._text_over = bytearray(st.text), st.text_over
        self._dots_hold = st.dots_hold
        self.stats = copy.deepcopy(st.stats)

    # ------------------------------------------------------------------ public
    def feed(self, data: bytes | bytearray | memoryview) -> list[Command]:
        data = bytes(data)
        self.stats.bytes_in += len(data)
        self._buf = None
        out: list[Command] = []
        i, n = 0, len(data)
        while i < n:
            mode = self.mode
            if mode is Mode.NGS:
                i = self._ngs(data, i, out)
            elif mode is Mode.AGS:
                i = self._ags(data, i, out)
            elif mode is Mode.ALPHA:
                i = self._alpha(data, i, out)
            elif mode is Mode.DOTS:
                i = self._dots(data, i, out)
            else:
                i = self._textmode(data, i, out)
        self.stats.commands += len(out)
        self._buf = self._xy = None
        return out

    # ------------------------------------------------------------------ alpha
    def _alpha(self, data: bytes, i: int, out: list[Command]) -> int:
        text = bytearray()
        n = len(data)
        while i < n:
            b = data[i]
            i += 1
            k = self._flag_k
            if k and b == GRAPHICS_FLAG[k]:
                self._flag_k = k + 1
                if self._flag_k == 4:
                    self._flag_k = 0
                    if text:
                        out.append(AlphaText(bytes(text)))
                    out.append(GraphicsFlag())
                    self.mode = Mode.NGS
                    return i
                continue
            if k:  # a false start: those bytes were text after all
                text += GRAPHICS_FLAG[:k]
                self._flag_k = 0
                self._line_start = False
            if b == 0x2B and (self._line_start or self.gh):
                self._flag_k = 1
                continue
            text.append(b)
            # a form feed starts a line too: PGPLOT's GOC driver erases the alpha screen with
            # BH FF +-*/ BH and expects the flag straight after the FF (docs/fidelity/sigma.md)
            self._line_start = b in (CR, LF, FF)
        if text:
            out.append(AlphaText(bytes(text)))
        return i

    # ------------------------------------------------------------------ NGS
    def _ngs(self, data: bytes, i: int, out: list[Command]) -> int:
        n = len(data)
        while i < n and self.mode is Mode.NGS:
            b = data[i]
            if 0x30 <= b <= 0x39 and self._idle():
                i = self._pairs(data, i, out)
                continue
            if self._ngs_byte(b, out):
                i += 1
        return i

    def _idle(self) -> bool:
        return (self._spec is None and not self._flag_k and self._letter < 0
                and not self._pair)

    def _pairs(self, data: bytes, i: int, out: list[Command]) -> int:
        """Fast path for a run of bare coordinate pairs (the bulk of an NGS drawing)."""
        m = _DIGITS.match(data, i)
        assert m is not None
        j = m.end()
        w = self.coord_digits
        whole = (j - i) // (2 * w) * (2 * w)
        if whole == 2 * w:
            out.append(Point(int(data[i:i + w]) - 100, int(data[i + w:i + 2 * w]) - 100))
        elif whole:  # a run: all its digits at once
            d = np.frombuffer(data, dtype=np.uint8, count=whole, offset=i).reshape(-1, 2, w)
            xy = (d.astype(np.int32) - 0x30) @ _TENS[4 - w:] - 100
            out.append(Points(xy))
        for b in data[i + whole:j]:  # a pair cut by the end of the feed or by a non-digit
            self._pair_byte(b, out)
        return j

    def _ngs_byte(self, b: int, out: list[Command]) -> bool:
        """Decode one byte in NGS; False means 'not consumed, decode it again'."""
        if self._spec is not None:
            return self._field_byte(b, out)
        if self._flag_k:
            if b == GRAPHICS_FLAG[self._flag_k]:
                self._flag_k += 1
                if self._flag_k == 4:
                    self._flag_k = 0
                    out.append(GraphicsFlag())
                return True
            self._flag_k = 0
            self.stats.malformed += 1
            return False
        if self._letter >= 0:
            if b == 0x2B:  # the graphics flag begins afresh: a lone letter before it is
                self._letter = -1  # dropped (PGPLOT's stray B after a cursor read)
                return False
            code = bytes((self._letter, b))
            spec = BY_CODE.get(code)
            if spec is None:
                self.stats.note_unknown(code.decode("latin-1"))
                self._letter = -1
                return False  # resynchronise: the second letter may start the next order
            self._letter = -1
            self._start_order(spec, out)
            return True
        if self._pair:
            return self._pair_byte(b, out)
        if 0x30 <= b <= 0x39:
            return self._pair_byte(b, out)
        if b in FIRST_LETTERS:
            self._letter = b
            return True
        if b == 0x2B:
            self._flag_k = 1
            return True
        if b in _IGNORED_IN_GRAPHICS or b == US:
            return True
        self.stats.note_unknown(f"0x{b:02X}")
        return True

    def _start_order(self, spec: OrderSpec, out: list[Command]) -> None:
        if spec.fields:
            self._spec = spec
            self._field_i = 0
            self._digits_left = spec.fields[0].width
            self._value = 0
            self._args = []
        else:
            self._finish_order(spec, (), out)

    def _field_byte(self, b: int, out: list[Command]) -> bool:
        spec = self._spec
        assert spec is not None
        field = spec.fields[self._field_i]
        d = digit_value(field.kind, b)
        if d < 0:
            self.stats.malformed += 1
            self._spec = None
            return False
        self._value = self._value * (10 if field.kind is Kind.DEC else 16) + d
        self._digits_left -= 1
        if self._digits_left == 0:
            self._args.append(self._value)
            self._field_i += 1
            self._value = 0
            if self._field_i == len(spec.fields):
                self._spec = None
                self._finish_order(spec, tuple(self._args), out)
            else:
                self._digits_left = spec.fields[self._field_i].width
        return True

    def _finish_order(self, spec: OrderSpec, args: tuple[int, ...], out: list[Command]) -> None:
        out.append(Order(spec.code, args))
        code = spec.code
        if code == "IO":
            self.coord_digits = 4
        elif code == "IP":
            self.coord_digits = 3
        elif code == "GH":
            self.gh = True
        elif code == "HH":
            self.coord_digits = 3
            self.gh = False
        if spec.mode is not None:
            self.mode = spec.mode
            if spec.mode is Mode.AGS:
                self._ags_state = abbreviated.new_state()
                self._ags_first = True
                self._esc = None
            elif spec.mode is Mode.TEXT:
                self._text = bytearray()
                self._text_over = False
            elif spec.mode is Mode.ALPHA:
                self._line_start = False
                self._flag_k = 0

    def _pair_byte(self, b: int, out: list[Command]) -> bool:
        if not 0x30 <= b <= 0x39:
            self.stats.malformed += 1
            self._pair = []
            return False
        self._pair.append(b - 0x30)
        w = self.coord_digits
        if len(self._pair) == 2 * w:
            x = y = 0
            for d in self._pair[:w]:
                x = x * 10 + d
            for d in self._pair[w:]:
                y = y * 10 + d
            self._pair = []
            out.append(Point(x - 100, y - 100))
        return True

    # ------------------------------------------------------------------ AGS
    def _ags(self, data: bytes, i: int, out: list[Command]) -> int:
        if self._esc is not None:
            return self._ags_escape(data, i, out)
        if self._buf is None:  # once per feed: the bytes as an array, room for every point
            # (a point can be a single LoX byte, so as many points as bytes)
            self._buf = np.frombuffer(data, dtype=np.uint8)
            self._xy = np.empty((len(data) + 1, 2), dtype=np.int32)
            self._k = 0
        k0 = self._k
        # the plain-Python scanner is much faster on bytes than on a numpy array
        buf = data if self.ags_scanner is abbreviated.scan_points else self._buf
        j, self._k = self.ags_scanner(buf, i, self._ags_state, self._xy, k0)
        if self._k > k0:
            out.append(AgsPoints(self._xy[k0:self._k].copy(), self._ags_first))
            self._ags_first = False
        if j >= len(data):
            return j
        if self._ags_state[abbreviated.PENDING]:
            self.stats.malformed += 1  # a point cut short by US / ESC
            self._ags_state[abbreviated.PENDING] = 0
        if data[j] == US:
            out.append(AgsEnd())
            self.mode = Mode.NGS
        else:
            self._esc = []
        return j + 1

    def _ags_escape(self, data: bytes, i: int, out: list[Command]) -> int:
        esc = self._esc
        assert esc is not None
        n = len(data)
        while i < n:
            b = data[i]
            if b < 0x20 or b > 0x7E:
                self.stats.malformed += 1
                self._esc = None
                return i  # decode this byte again in AGS
            esc.append(b)
            i += 1
            if len(esc) == 4:
                out.append(AgsEscape(chr(esc[0]), bytes(esc[1:])))
                self._esc = None
                return i
        return i

    # ------------------------------------------------------------------ DJ dots
    def _dots(self, data: bytes, i: int, out: list[Command]) -> int:
        """One hex digit per pixel until Z or another byte. A dot A-F followed at once by a
        letter that is not a hex digit, the two forming an order (``DJ12BH``: BH), is taken
        as that order: it ends dot plotting. Pairs of two hex letters (``FA``, ``CA``...) are
        always dots — hosts end DJ with Z before such orders."""
        n = len(data)
        px = bytearray()
        hold = self._dots_hold
        while i < n:
            b = data[i]
            if hold >= 0:
                self._dots_hold = -1
                if digit_value(Kind.HEX, b) < 0 and bytes((hold, b)) in BY_CODE:
                    if px:
                        out.append(Dots(bytes(px)))
                    self.mode = Mode.NGS
                    self._letter = hold  # b completes the order in NGS
                    return i
                px.append(digit_value(Kind.HEX, hold))
                hold = -1
            d = digit_value(Kind.HEX, b)
            if d >= 0:
                i += 1
                if b >= 0x41 and b in FIRST_LETTERS:  # may start an order: decide on the next
                    hold = b
                    continue
                px.append(d)
                continue
            if px:
                out.append(Dots(bytes(px)))
                px = bytearray()
            if b == 0x5A:  # Z
                out.append(DotsEnd())
                self.mode = Mode.NGS
                return i + 1
            if b in _IGNORED_IN_GRAPHICS:
                i += 1
                continue
            self.mode = Mode.NGS  # anything else ends dot plotting and is decoded as NGS
            return i
        if px:
            out.append(Dots(bytes(px)))
        self._dots_hold = hold
        return i

    # ------------------------------------------------------------------ BA text
    def _textmode(self, data: bytes, i: int, out: list[Command]) -> int:
        n = len(data)
        j = data.find(b"\r", i)
        end = n if j < 0 else j
        for b in data[i:end]:
            if 0x20 <= b <= 0x7E:
                if len(self._text) < self.MAX_TEXT:
                    self._text.append(b)
                elif not self._text_over:
                    self._text_over = True
                    self.stats.malformed += 1
        if j < 0:
            return n
        out.append(GraphicsText(bytes(self._text)))
        self._text = bytearray()
        self.mode = Mode.NGS
        return j + 1
