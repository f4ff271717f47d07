"""Protocol traces: every order a terminal decodes, with its byte offset, virtual time,
decoded arguments and any warning (unknown, malformed, out of range), for host authors.

Tracing feeds the terminal one byte at a time (the decoder is built to be split anywhere,
so the picture is the same) and compares the decoder's counters around each byte; with
tracing off nothing here runs, so the fast paths of ``Terminal.feed`` are untouched.
``strict`` raises ``ProtocolError`` for the first warning once the piece of input that
held it has been fed (so the terminal and the line stay consistent and may carry on).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from camlab88.emulator.protocol_trace import ProtocolError, TraceEvent
from camlab88.protocols.sigma import commands as sc
from camlab88.protocols.sigma.orders import BY_CODE, ORDERS, Mode

if TYPE_CHECKING:
    from camlab88.emulator.sigma.terminal import Terminal

CONTEXT = 12  # bytes shown before the offending one
__all__ = ["ProtocolError", "SigmaTracer", "TraceEvent"]


def _field_text(code: str) -> str:
    spec = BY_CODE[code.encode()]
    if not spec.fields:
        return f"{code} (no parameters)"
    parts = ", ".join(f"{f.name}: {f.width} {f.kind.value} digit(s)" for f in spec.fields)
    return f"{code} then {parts}"


def _after_letter(letter: str) -> str:
    codes = sorted(o.code for o in ORDERS if o.code[0] == letter)
    return f"an order of the table: after {letter!r} one of {', '.join(codes)}"


class SigmaTracer:
    """Feeds a terminal byte by byte and reports each order to ``sink``."""

    def __init__(self, term: Terminal, sink: Callable[[TraceEvent], None],
                 strict: bool = False) -> None:
        self.term, self.sink, self.strict = term, sink, strict
        self.offset = 0  # stream offset of the next byte
        self.start = 0  # offset of the first byte of the order being read
        self.recent = bytearray()
        self.warnings = 0
        self._first: TraceEvent | None = None  # strict: the first problem of this piece

    def feed(self, data: bytes, t_first: float = 0.0, step: float = 0.0,
             times: Sequence[float] | None = None) -> None:
        """``data``'s byte k arrived at ``times[k]``, or ``t_first + k * step``, virtual s."""
        term, dec = self.term, self.term.decoder
        alpha: TraceEvent | None = None
        for k, b in enumerate(data):
            off = self.offset + k
            t = float(times[k]) if times is not None else t_first + k * step
            self.recent = (self.recent + bytes((b,)))[-CONTEXT:]
            before = self._before()
            cmds = dec.feed(bytes((b,)))
            term._run(cmds)
            for ev in self._describe(cmds, t):
                if ev.order == "alpha" and alpha is not None:
                    alpha.args["text"] += ev.args["text"]
                    alpha.time = t
                    continue
                if alpha is not None:
                    self._emit(alpha)
                    alpha = None
                if ev.order == "alpha":
                    alpha = ev
                else:
                    self._emit(ev)
            if before[4] >= 0 and b == 0x2B and before[0] == dec.stats.unknown:
                # a lone order letter dropped at the graphics flag (not an error: PGPLOT's
                # GOC driver leaves a stray B after every cursor read)
                self._emit(TraceEvent(off - 1, t, "dropped", {"letter": chr(before[4])}))
                self.start = off
            problems = self._problems(before, b, cmds, off, t)
            if problems and alpha is not None:
                self._emit(alpha)
                alpha = None
            for problem in problems:
                self._emit(problem)
            if cmds or problems or self._idle():
                self.start = off + 1
        if alpha is not None:
            self._emit(alpha)
        self.offset += len(data)
        if self._first is not None:  # strict: raised once the piece is in, so the terminal
            first, self._first = self._first, None  # and the line stay consistent
            raise ProtocolError(first)

    def cut_short(self, t: float, why: str) -> None:
        """The order under way will never be finished (``why``: its sender hung up): one
        malformed event, worded as when a byte cuts an order short; strict raises it."""
        dec = self.term.decoder
        expected = (_after_letter(chr(dec._letter)) if dec._spec is None and dec._letter >= 0
                    else self._expected(dec._spec, list(dec._pair), dec._flag_k, dec.mode))
        ev = TraceEvent(self.start, t, "malformed", {}, f"{why} cuts an order short",
                        "malformed", expected, bytes(self.recent))
        self._emit(ev)
        self.start = self.offset
        if self.strict:
            raise ProtocolError(ev)

    def _emit(self, ev: TraceEvent) -> None:
        self.sink(ev)
        if ev.warning is not None:
            self.warnings += 1
            if self.strict and self._first is None:
                self._first = ev

    def _idle(self) -> bool:
        dec = self.term.decoder
        return dec.mode in (Mode.NGS, Mode.ALPHA) and dec._idle() and dec._dots_hold < 0

    def _before(self) -> tuple[Any, ...]:
        dec, s = self.term.decoder, self.term.decoder.stats
        return (s.unknown, s.malformed, self.term.errors, dec._spec, dec._letter,
                list(dec._pair), dec._flag_k, dec.mode, dec._esc is not None)

    # ------------------------------------------------------------------ orders
    def _describe(self, cmds: list[Any], t: float) -> list[TraceEvent]:
        out = []
        for c in cmds:
            out.extend(self._one(c, t))
        return out

    def _one(self, c: Any, t: float) -> list[TraceEvent]:
        at = self.start
        if isinstance(c, sc.Order):
            fields = BY_CODE[c.code.encode()].fields
            return [TraceEvent(at, t, c.code, {f.name: v for f, v in zip(fields, c.args)})]
        if isinstance(c, sc.Point):
            pen = "draw" if self.term.reg.pen_down else "move"
            return [TraceEvent(at, t, "pair", {"x": c.x, "y": c.y, "pen": pen})]
        if isinstance(c, sc.Points | sc.AgsPoints):
            name = "ags point" if isinstance(c, sc.AgsPoints) else "pair"
            return [TraceEvent(at, t, name, {"x": int(x), "y": int(y)}) for x, y in c.xy]
        if isinstance(c, sc.AlphaText):
            return [TraceEvent(at, t, "alpha", {"text": c.data.decode("latin-1")})]
        if isinstance(c, sc.GraphicsText):
            return [TraceEvent(at, t, "BA text", {"text": c.text.decode("latin-1")})]
        if isinstance(c, sc.Dots):
            return [TraceEvent(at, t, "dots", {"colours": c.colours.hex()})]
        if isinstance(c, sc.AgsEscape):
            return [TraceEvent(at, t, "ESC", {"letter": c.letter,
                                              "param": c.param.decode("latin-1")})]
        names = {sc.GraphicsFlag: "+-*/", sc.AgsEnd: "US", sc.DotsEnd: "Z"}
        return [TraceEvent(at, t, names.get(type(c), type(c).__name__))]

    # ------------------------------------------------------------------ problems
    def _problems(self, before: tuple[Any, ...], b: int, cmds: list[Any], off: int,
                  t: float) -> list[TraceEvent]:
        """Every counter step this byte caused, in the order the decoder took them: a field
        cut short, then the byte decoded afresh (an unknown order, an unknown byte), then
        what the terminal refused."""
        s = self.term.decoder.stats
        unknown, malformed, errors, spec, letter, pair, flag_k, mode, esc = before
        ctx = bytes(self.recent)
        out = [TraceEvent(self.start, t, "malformed", {},
                          f"byte 0x{b:02X} ({chr(b)!r}) cuts an order short", "malformed",
                          self._expected(spec, pair, flag_k, mode), ctx)
               for _ in range(s.malformed - malformed)]
        new_unknown = s.unknown - unknown
        if new_unknown and letter >= 0:
            code = chr(letter) + chr(b)
            out.append(TraceEvent(off - 1, t, code, {}, f"unknown order {code!r}", "unknown",
                                  _after_letter(chr(letter)), ctx))
            new_unknown -= 1
        for _ in range(new_unknown):
            if mode is Mode.AGS or esc:
                out.append(TraceEvent(off, t, "ESC", {}, "unknown ESC sequence in abbreviated "
                                      "mode", "unknown", "ESC M hhh or ESC R", ctx))
            else:
                out.append(TraceEvent(off, t, f"0x{b:02X}", {}, f"unknown byte 0x{b:02X} in "
                                      "graphics mode", "unknown",
                                      "an order letter, a digit, or +-*/", ctx))
        if self.term.errors > errors:
            order = next((c for c in reversed(cmds) if isinstance(c, sc.Order)), None)
            code = order.code if order is not None else "?"
            args = list(order.args) if order is not None else []
            out.append(TraceEvent(self.start, t, code, {"values": args},
                                  f"{code}{args} is out of range on a {self.term.model.name}",
                                  "out of range", self._range(code), ctx))
        return out

    def _expected(self, spec: Any, pair: list[int], flag_k: int, mode: Mode) -> str:
        if spec is not None:
            return _field_text(spec.code)
        if pair:
            w = self.term.decoder.coord_digits
            return f"a coordinate pair of 2 x {w} decimal digits (x + 100, y + 100)"
        if flag_k:
            return "the graphics flag +-*/ complete"
        if mode is Mode.AGS:
            return "an abbreviated-mode point HiY [EB] LoY HiX LoX, ended by US"
        if mode is Mode.TEXT:
            return "BA text of at most 256 printable characters, then CR"
        return "ESC letter and 3 printable characters"

    def _range(self, code: str) -> str:
        m = self.term.model
        if code == "KQ":
            return "KQ0-KQ4 on a T5688 (a T5684 has one view)"
        if code in ("JG", "KG"):
            return f"a LUT index below {m.lut_entries}"
        if code in ("JM", "JN"):
            return "a size of at least 1000 (10 x (radius + 100)) and a JO ratio above 100"
        return _field_text(code) if code != "?" else "a value the order accepts"
