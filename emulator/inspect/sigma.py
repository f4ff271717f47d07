"""The Sigma inspector panel: the LUT as swatches, each bit plane on its own, the write and
display masks, alpha/graphics mode, the pen and the cursor, and the last orders decoded
(emulator.sigma.trace.SigmaTracer, fed the terminal's bytes instead of its own ``feed``:
tracing feeds byte by byte, and the picture is the same)."""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from fractions import Fraction
from typing import Any

import numpy as np

from camlab88.emulator.inspect import draw
from camlab88.emulator.protocol_trace import TraceEvent

ORDERS_KEPT = 14


def order_text(ev: TraceEvent) -> str:
    """One decoded order as a short line: ``HI colour=3``, ``pair 120,40 draw``."""
    if ev.warning:
        return f"! {ev.warning}"
    args = ev.args
    if ev.order in ("pair", "ags point"):
        return f"{ev.order} {args.get('x')},{args.get('y')} {args.get('pen', '')}".rstrip()
    if "text" in args:
        return f"{ev.order} {args['text']!r}"
    return f"{ev.order} " + " ".join(f"{k}={v}" for k, v in args.items())


class SigmaPanel:
    """Draws the panel for ``term`` (emulator.sigma.Terminal); ``time()`` is virtual s.
    Made once per run: it starts tracing the terminal's input so it can list orders."""

    def __init__(self, term: Any, time: Callable[[], Fraction], width: int) -> None:
        self.term, self.time, self.width = term, time, width
        self.orders: deque[str] = deque(maxlen=ORDERS_KEPT)
        self._tap(term)

    def _tap(self, term: Any) -> None:
        from camlab88.emulator.sigma.trace import SigmaTracer

        tracer = SigmaTracer(term, self._note)
        tracer.offset = tracer.start = term.decoder.stats.bytes_in
        term.feed = lambda data: tracer.feed(bytes(data), float(self.time()))

    def _note(self, ev: TraceEvent) -> None:
        self.orders.append(order_text(ev))

    def __call__(self, frame: np.ndarray) -> np.ndarray:
        img = draw.canvas(self.width, frame.shape[0])
        m = self.term.model
        draw.text(img, 6, 4, f"SIGMA {m.name.upper()}   t {float(self.time()):.2f} s",
                  draw.ACCENT)
        y = self._lut(img, 18)
        y = self._planes(img, y + 4)
        y = self._registers(img, y + 4)
        draw.text(img, 6, y + 4, "last orders", draw.ACCENT)
        _, ch = draw.cell()
        room = max(0, (img.shape[0] - y - 16) // ch)
        shown = list(self.orders)[-room:] if room else []  # the latest that fit
        for i, line in enumerate(shown):
            draw.text(img, 6, y + 16 + i * ch, line[: self.width // 6 - 2])
        return img

    def _lut(self, img: np.ndarray, y: int) -> int:
        lut = self.term.lut
        n = len(lut)
        per_row = 16
        size = (self.width - 12) // per_row
        side = size if n <= 16 else max(4, size // 2)
        draw.text(img, 6, y, f"LUT ({n} entries)", draw.ACCENT)
        y += 12
        for i in range(n):
            r, c = divmod(i, per_row)
            x0, y0 = 6 + c * size, y + r * side
            draw.fill(img, x0, y0, size - 1, side - 1, tuple(int(v) for v in lut[i]))
            if n <= 16:
                draw.text(img, x0 + 2, y0 + side, f"{i:X}", draw.DIM)
        rows = -(-n // per_row)
        return y + rows * side + (12 if n <= 16 else 2)

    def _planes(self, img: np.ndarray, y: int) -> int:
        t = self.term
        planes = t.planes  # [y, x], y up
        k = t.model.planes
        per_row = 4
        cw = (self.width - 12) // per_row
        w, h = cw - 4, (cw - 4) * planes.shape[0] // planes.shape[1]
        # each thumbnail pixel ORs its block, so one-pixel lines stay visible
        ys = np.arange(h) * planes.shape[0] // h
        xs = np.arange(w) * planes.shape[1] // w
        small = np.bitwise_or.reduceat(np.bitwise_or.reduceat(planes[::-1], ys, axis=0),
                                       xs, axis=1)
        draw.text(img, 6, y, "planes (write mask: lit frame)", draw.ACCENT)
        y += 12
        for p in range(k):
            r, c = divmod(p, per_row)
            x0, y0 = 6 + c * cw, y + r * (h + 14)
            thumb = img[y0:y0 + h, x0:x0 + w]
            thumb[:] = (0, 0, 0)
            thumb[(small >> p) & 1 == 1] = draw.INK
            lit = (t.reg.write_mask >> p) & 1
            draw.frame_box(img, x0 - 1, y0 - 1, w + 2, h + 2, draw.ACCENT if lit else draw.DIM)
            draw.text(img, x0, y0 + h + 2, f"plane {p}", draw.INK if lit else draw.DIM)
        return y + -(-k // per_row) * (h + 14)

    def _registers(self, img: np.ndarray, y: int) -> int:
        r, k = self.term.reg, self.term.model.planes
        mode = self.term.decoder.mode.value
        lines = [
            f"write mask {r.write_mask:0{k}b}  display mask {r.display_mask:0{k}b}",
            f"alpha {'on' if r.alpha_on else 'off'}  graphics {'on' if r.graphics_on else 'off'}"
            f"  decoder {mode}  view {r.view}",
            f"colour {r.colour}  pen {r.pen_x},{r.pen_y} {'down' if r.pen_down else 'up'}"
            f"  {'dashed' if r.line_dashed else 'solid'}",
            f"cursor {'on' if r.cursor_on else 'off'} at {r.cursor_x},{r.cursor_y} "
            f"shape {r.cursor_shape}{' reading' if r.cursor_report else ''}",
            f"alpha cursor row {self.term.alpha.row} col {self.term.alpha.col}",
        ]
        _, ch = draw.cell()
        for i, line in enumerate(lines):
            draw.text(img, 6, y + i * ch, line)
        return y + len(lines) * ch
