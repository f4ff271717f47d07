"""What every KAS front shares: Sigma set-up, the stylus cursor, incremental updates.

A front is driven by a ``Session`` (apps.kas.program.script) or a window loop: ``start()``
gives the set-up bytes, ``pointer()`` takes input-layer events, ``keys()`` the bytes the
terminal's keyboard sent up the line, and ``update()`` the bytes that bring the screen up
to date (the caller sends them when the line has drained, so updates coalesce).
"""

from __future__ import annotations

from camlab88.apps.kas.program import layout as L
from camlab88.apps.kas.program.draw import Painter, Prim
from camlab88.apps.quitting import QUIT_QUESTION, AsksBeforeQuitting
from camlab88.protocols.sigma import Encoder
from camlab88.protocols.sigma.keyboard import bytes_to_keys
from camlab88.protocols.tablets.input_layer import PointerEvent


def setup_bytes(enc: Encoder, lut: list[tuple[int, int, int]], cursor: bool = True) -> bytes:
    """Into graphics mode, reset, graphics only, all planes, the LUT, the stylus cursor."""
    out = bytearray(enc.take_over())
    out += enc.sequence_length(0) + enc.graphics_on() + enc.alpha_off()
    out += enc.write_mask(0x0F) + enc.display_mask(0x0F) + enc.line_solid()
    for i, (r, g, b) in enumerate(lut):
        out += enc.lut(i, r, g, b)
    if cursor:
        # the stylus cursor is the terminal's own cross, attached to the pen: parking the
        # pen at the stylus moves it without touching the planes
        out += enc.cursor_shape(2) + enc.cursor_attach() + enc.cursor_on()
    else:
        out += enc.cursor_off()
    return bytes(out)


class Front(AsksBeforeQuitting):
    """Base of the editor and path fronts: subclasses give ``prims()`` and handle input.

    Quitting (Esc with no command to cancel, or the window's close button) is the same for
    every front (apps.quitting)."""

    def __init__(self, background: str = "black") -> None:
        self.enc = Encoder()
        self.painter = Painter(self.enc)
        self.lut = L.lut_plan(background)
        self.background = background
        self.stylus_px: tuple[int, int] = (round(L.CENTRE_X), round(L.CENTRE_Y))
        self._parked: tuple[int, int] | None = None
        self.done = False
        self.quitting = False   # the program should end (its harness target stops)
        self.discarded = False  # ... and the user chose to drop unsaved work
        self.asking = False     # the quit question is on the message line
        self.notices: list[str] = []
        self._sent_lut: list[tuple[int, int, int]] = []

    # -- to be provided --------------------------------------------------------------------
    def prims(self) -> list[Prim]:
        raise NotImplementedError

    def on_pointer(self, x: float, y: float, down: bool) -> None:
        """Stylus in screen field inches."""
        raise NotImplementedError

    def on_key(self, key: str) -> None:
        raise NotImplementedError

    def current_lut(self) -> list[tuple[int, int, int]]:
        """The LUT the screen needs now (the editor reloads its dim entries, §3.1.1)."""
        return self.lut

    def unsaved(self) -> bool:
        """Is there work a quit would lose?"""
        return False

    def save_work(self) -> bool:
        """Save it (as F2 does); False if the save failed (the message line says why)."""
        return True

    def say(self, message: str) -> None:
        """Put ``message`` on the program's message line."""

    def ask_quit(self) -> None:
        self.say(QUIT_QUESTION)

    def stay(self) -> None:
        self.say("")

    def end(self) -> None:
        self.quitting = True

    # -- driving ---------------------------------------------------------------------------
    def start(self) -> bytes:
        self._sent_lut = self.current_lut()
        out = setup_bytes(self.enc, self._sent_lut) + self.painter.full(self.prims())
        return out + self._park()

    def pointer(self, events: list[PointerEvent]) -> None:
        for ev in events:
            fx, fy = L.tablet_to_field(ev.x, ev.y)
            sx, sy = L.field_to_px(fx, fy)
            self.stylus_px = (min(max(round(sx), 0), L.SCREEN_W - 1),
                              min(max(round(sy), 0), L.SCREEN_H - 1))
            self.on_pointer(fx, fy, ev.down)

    def keys(self, data: bytes) -> None:
        for k in bytes_to_keys(data):
            if self.quitting:
                return
            if self.asking:
                self.answer_quit(k)
            else:
                self.on_key(k)

    def update(self) -> bytes:
        out = self._lut_changes() + self.painter.update(self.prims())
        if out or self._parked != self.stylus_px:
            out += self._park()
        return out

    def redraw(self) -> bytes:
        """Everything again from scratch (for comparison with the incremental screen)."""
        return self.painter.full(self.prims()) + self._park()

    def _lut_changes(self) -> bytes:
        """LUT orders for the entries whose colour changed: the terminal recolours what is
        drawn in them at once (facts/sigma.md), so nothing is redrawn for it."""
        lut = self.current_lut()
        out = bytearray()
        for i, rgb in enumerate(lut):
            if i >= len(self._sent_lut) or self._sent_lut[i] != rgb:
                out += self.enc.lut(i, *rgb)
        self._sent_lut = lut
        return bytes(out)

    def _park(self) -> bytes:
        self._parked = self.stylus_px
        return self.enc.move(*self.stylus_px)
