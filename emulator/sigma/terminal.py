"""The Sigma T5684 / T5688 terminal: decoder + registers + plane store + LUT + alpha + cursor.

Bytes go in with ``feed`` (split anywhere); ``frame`` is what the monitor shows (graphics
over alpha, cursor on top); bytes the terminal sends up the line go to ``on_output``.
Registers are named after the orders that set them (see protocols.sigma.orders).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, fields

import numpy as np

from camlab88.emulator.sigma import display, raster
from camlab88.emulator.sigma.alpha import AlphaScreen
from camlab88.emulator.sigma.fast import scan_points_fast
from camlab88.emulator.sigma.models import Model, get_model
from camlab88.protocols.sigma import (
    AgsEscape,
    AgsPoints,
    AlphaText,
    Command,
    Decoder,
    Dots,
    GraphicsText,
    Order,
    Point,
    Points,
    format_report,
)
from camlab88.protocols.sigma.decoder_state import check_keys
from camlab88.protocols.sigma.keyboard import CURSOR_STEPS, KEY_BYTES
from camlab88.roms.sigma import load_font, load_lut

TEXT_CELL_W = 8  # graphics text (BA) advance, reconstructed
TABLET_KEY = ord("1")  # the key byte a stylus press reports (reconstructed)
AGS_DASHED_12 = 0xE38  # ESC R: built-in dashed pattern, 3 on 3 off (GUESS)
FEED_PIECE = 1 << 16


@dataclass
class Registers:
    """Everything the orders set. Names follow protocols.sigma.orders."""

    @classmethod
    def from_json(cls, regs: object) -> Registers:
        """asdict()'s mapping back, every register present and of its type (ValueError)."""
        if not isinstance(regs, dict):
            raise ValueError("Sigma state 'registers' is not a mapping")
        check_keys(regs, [f.name for f in fields(cls)], "register")
        defaults = cls()
        for name, v in regs.items():
            want = type(getattr(defaults, name))
            if type(v) is not want or (want is int and not -(1 << 31) <= v < 1 << 31):
                raise ValueError(f"Sigma state register {name!r}={v!r} is not a "
                                 f"{want.__name__}")
        return cls(**regs)

    pen_x: int = 0
    pen_y: int = 0
    pen_down: bool = False  # GI / GJ
    continuing: bool = False  # the pen is the end of the last vector (polyline)
    colour: int = 1  # HI, KI, FA, FB
    write_mask: int = 0xFF  # KW
    display_mask: int = 0xFF  # KD
    line_dashed: bool = False  # FC / FD
    dash_mask: int = 0xFFFF  # DL (16 bits), ESC M / EK (12 bits)
    dash_bits: int = 16
    dash_phase: int = 0
    ellipse_ratio: int = 356  # JO field as sent: 256 * major / minor + 100
    solid_shape: bool = False  # FH, one-shot
    block: bool = False  # BG, one-shot
    graphics_on: bool = True  # GA
    alpha_on: bool = True  # AA / AJ
    cursor_on: bool = False  # CA / CB
    cursor_attach: bool = False  # CE
    cursor_tablet: bool = False  # CF (joystick) / GM3 (tablet)
    cursor_shape: int = 1  # CK
    cursor_x: int = 0
    cursor_y: int = 0
    cursor_report: bool = False  # HF armed
    view: int = 0  # KQ: 0-3 quadrant, 4 whole area at half size
    sequence_length: int = 0  # DD
    xon_char: int = 17  # DG
    xoff_char: int = 19  # DF
    prompt_char: int = 999  # HE


class Terminal:
    """A Sigma T5684 or T5688 (docs/interfaces.md)."""

    def __init__(self, model: str = "t5684") -> None:
        self.model: Model = get_model(model)
        self.on_output: Callable[[bytes], None] | None = None
        self.decoder = Decoder(ags_scanner=scan_points_fast)
        self.errors = 0  # orders with impossible values (e.g. a negative ellipse)
        self._font = load_font()
        self._handlers: dict[str, Callable[[tuple[int, ...]], None]] = self._order_handlers()
        self.power_on()

    # ------------------------------------------------------------------ life cycle
    def power_on(self) -> None:
        self._device_reset()
        self.decoder.power_on()

    def _device_reset(self) -> None:
        m = self.model
        self.planes = np.zeros((m.area_h, m.area_w), dtype=np.uint8)  # [y, x], y up
        self.lut = load_lut(m.name)  # (entries, 3) uint8, a fresh copy
        self.alpha = AlphaScreen()
        self.reg = Registers(write_mask=m.plane_mask, display_mask=m.plane_mask)

    @property
    def stats(self) -> dict[str, int]:
        s = self.decoder.stats
        return {"unknown": s.unknown, "malformed": s.malformed, "errors": self.errors,
                "bytes": s.bytes_in, "commands": s.commands}

    # ------------------------------------------------------------------ the line
    def feed(self, data: bytes) -> None:
        # in pieces, so the decoder's per-feed work arrays stay small whatever the input
        for i in range(0, len(data), FEED_PIECE):
            self._run(self.decoder.feed(data[i:i + FEED_PIECE]))

    def _run(self, commands: list[Command]) -> None:
        for cmd in commands:
            t = type(cmd)
            if t is AgsPoints:
                self._ags_points(cmd)
            elif t is Point:
                self._point(cmd.x, cmd.y)
            elif t is Points:
                self._points(cmd.xy)
            elif t is Order:
                self._handlers[cmd.code](cmd.args)
            elif t is AlphaText:
                self.alpha.write(cmd.data)
            elif t is Dots:
                self._dots(cmd.colours)
            elif t is GraphicsText:
                self._text(cmd.text)
            elif t is AgsEscape:
                self._ags_escape(cmd)
            # GraphicsFlag, AgsEnd and DotsEnd only switch the decoder's mode: nothing to draw

    def _send(self, data: bytes) -> None:
        if self.on_output is not None:
            self.on_output(data)

    # ------------------------------------------------------------------ drawing
    @property
    def _dash(self) -> tuple[int, int]:
        r = self.reg
        return (r.dash_mask, r.dash_bits) if r.line_dashed else (0, 0)

    def _move(self, x: int, y: int) -> None:
        r = self.reg
        r.pen_x, r.pen_y = x, y
        r.continuing = False
        if r.cursor_attach:
            r.cursor_x, r.cursor_y = self._clip_area(x, y)

    def _line_to(self, x: int, y: int) -> None:
        r = self.reg
        dash, bits = self._dash
        r.dash_phase = raster.draw_line(self.planes, r.pen_x, r.pen_y, x, y, r.colour,
                                        r.write_mask, dash, bits, r.dash_phase, r.continuing)
        self._move(x, y)
        r.continuing = True

    def _point(self, x: int, y: int) -> None:
        r = self.reg
        if r.block:
            self._block(x, y)
        elif r.pen_down:
            self._line_to(x, y)
        else:
            self._move(x, y)

    def _points(self, xy: np.ndarray) -> None:
        """A run of NGS pairs: one polyline (pen down) or one move to the last (pen up)."""
        r = self.reg
        if r.block:  # the first pair is a block corner; the rest go on as usual
            self._block(int(xy[0, 0]), int(xy[0, 1]))
            xy = xy[1:]
            if len(xy) == 0:
                return
        if not r.pen_down:
            self._move(int(xy[-1, 0]), int(xy[-1, 1]))
            return
        self._polyline_from_pen(xy)

    def _polyline_from_pen(self, xy) -> None:
        """Draw from the pen through ``xy`` (dashed as set, the dash carried on), leaving the
        pen at the last point."""
        r = self.reg
        dash, bits = self._dash
        r.dash_phase = raster.draw_polyline(self.planes, xy, r.pen_x, r.pen_y, r.colour,
                                            r.write_mask, dash, bits, r.dash_phase,
                                            r.continuing)
        self._move(int(xy[-1, 0]), int(xy[-1, 1]))
        r.continuing = True

    def _block(self, x: int, y: int) -> None:
        r = self.reg
        if r.solid_shape:
            raster.fill_rect(self.planes, r.pen_x, r.pen_y, x, y, r.colour, r.write_mask)
        else:
            x0, y0 = r.pen_x, r.pen_y
            for (ax, ay), (bx, by) in (((x0, y0), (x, y0)), ((x, y0), (x, y)),
                                       ((x, y), (x0, y)), ((x0, y), (x0, y0))):
                raster.draw_line(self.planes, ax, ay, bx, by, r.colour, r.write_mask, 0, 0, 0,
                                 False)
        r.block = r.solid_shape = False
        self._move(x, y)

    def _ags_points(self, cmd: AgsPoints) -> None:
        xy = cmd.xy
        if cmd.move_first:
            self._move(int(xy[0, 0]), int(xy[0, 1]))
            xy = xy[1:]
        if len(xy) == 0:
            return
        self._polyline_from_pen(xy)

    def _ags_escape(self, cmd: AgsEscape) -> None:
        r = self.reg
        if cmd.letter == "M":
            try:
                r.dash_mask, r.dash_bits = int(cmd.param.decode("ascii"), 16), 12
            except ValueError:
                self.decoder.stats.malformed += 1
        elif cmd.letter == "R":
            r.dash_mask, r.dash_bits = AGS_DASHED_12, 12
        else:
            self.decoder.stats.note_unknown("ESC " + cmd.letter)

    def _dots(self, colours: bytes) -> None:
        # each dot advances the pen, so DJ ... Z, a flush, DJ again carries on along the row
        r = self.reg
        c = np.frombuffer(colours, dtype=np.uint8)
        r.pen_x = raster.dot_run(self.planes, r.pen_x, r.pen_y, c, r.write_mask)
        r.continuing = False

    def _text(self, text: bytes) -> None:
        r = self.reg
        f = self._font
        for ch in text:
            g = f.glyph(ch)[::-1]  # row 0 = bottom descender row
            raster.write_mask_at(self.planes, g, r.pen_x + 1, r.pen_y + 1, r.colour, r.write_mask)
            r.pen_x += TEXT_CELL_W
        r.continuing = False

    def _ellipse(self, size: int, solid: bool) -> None:
        r = self.reg
        a = size / 10.0 - 100.0
        ratio = (r.ellipse_ratio - 100) / 256.0
        if a < 0 or ratio <= 0:
            self.errors += 1
            return
        m = self.model
        shape, x0, y0 = raster.ellipse_pixels(r.pen_x, r.pen_y, a, a / ratio, m.area_w,
                                              m.area_h, solid)
        raster.write_mask_at(self.planes, shape, x0, y0, r.colour, r.write_mask)

    def _fill(self, boundary: int) -> None:
        r = self.reg
        pm = self.model.plane_mask
        raster.boundary_fill(self.planes, r.pen_x, r.pen_y, r.colour, r.write_mask,
                             boundary & pm, r.display_mask)

    def _erase(self) -> None:
        self.planes &= np.uint8(~self.reg.write_mask & 0xFF)

    def _lut(self, index: int, red: int, green: int, blue: int, bits: int) -> None:
        if index >= len(self.lut):
            self.errors += 1
            return
        # plain ints, not a numpy array per entry: a LUT load is hundreds of these orders
        rgb = (red, green, blue)
        if bits == 4:
            rgb = tuple(v * 17 for v in rgb)
        if self.model.gun_bits == 4:
            rgb = tuple((v >> 4) * 17 for v in rgb)  # a 4096-colour LUT keeps 4 bits per gun
        self.lut[index] = tuple(v & 0xFF for v in rgb)  # as uint8 arithmetic wraps

    def _reset(self) -> None:
        # HH: the device side only; the decoder has already reset its own coordinate width
        # and GH, and stays in graphics mode because the host carries on with orders.
        self._device_reset()

    # ------------------------------------------------------------------ order table
    def _order_handlers(self) -> dict[str, Callable[[tuple[int, ...]], None]]:
        r = lambda: self.reg  # noqa: E731 - registers are replaced by HH
        pm = lambda: self.model.plane_mask  # noqa: E731

        def setr(**kw: object) -> Callable[[tuple[int, ...]], None]:
            def go(_args: tuple[int, ...]) -> None:
                for k, v in kw.items():
                    setattr(r(), k, v)
            return go

        def arg(name: str, fn: Callable[[int], int] = lambda v: v) -> Callable[..., None]:
            def go(args: tuple[int, ...]) -> None:
                setattr(r(), name, fn(args[0]))
            return go

        def nothing(_args: tuple[int, ...]) -> None:
            return None

        def fg(_args: tuple[int, ...]) -> None:
            r().dash_phase = 0

        def view(args: tuple[int, ...]) -> None:
            if self.model.high_res and args[0] <= 4:
                r().view = args[0]
            else:
                self.errors += 1

        def report(_args: tuple[int, ...]) -> None:
            r().cursor_report = True

        def joystick(_args: tuple[int, ...]) -> None:
            r().cursor_tablet = False

        def device(args: tuple[int, ...]) -> None:
            r().cursor_tablet = args[0] == 3

        def attach(_args: tuple[int, ...]) -> None:
            r().cursor_attach = True
            r().cursor_x, r().cursor_y = self._clip_area(r().pen_x, r().pen_y)

        def dash12(args: tuple[int, ...]) -> None:
            r().dash_mask, r().dash_bits = args[0], 12

        def dash16(args: tuple[int, ...]) -> None:
            r().dash_mask, r().dash_bits = args[0], 16

        return {
            "BH": nothing, "HH": lambda a: self._reset(), "DD": arg("sequence_length"),
            "DG": arg("xon_char"), "DF": arg("xoff_char"),
            "GA": setr(graphics_on=True), "AA": setr(alpha_on=True), "AJ": setr(alpha_on=False),
            "HE": arg("prompt_char"), "CK": arg("cursor_shape"), "GH": nothing, "IE": joystick,
            "IO": nothing, "IP": nothing,  # the decoder keeps the coordinate width
            "DA": lambda a: self._erase(),
            "GI": setr(pen_down=False), "GJ": setr(pen_down=True),
            "FA": setr(colour=1), "FB": setr(colour=0),
            "FC": setr(line_dashed=False), "FD": setr(line_dashed=True), "FG": fg,
            "DL": dash16, "EK": dash12,
            "HI": arg("colour"), "KI": arg("colour", lambda v: v & pm()),
            "BA": nothing, "FH": setr(solid_shape=True), "BG": setr(block=True), "DJ": nothing,
            "JK": lambda a: self._fill(a[0]), "KK": lambda a: self._fill(a[0]),
            "JO": arg("ellipse_ratio"),
            "JM": lambda a: self._ellipse(a[0], False), "JN": lambda a: self._ellipse(a[0], True),
            "JH": nothing,
            "JG": lambda a: self._lut(a[0], a[1], a[2], a[3], 4),
            "KG": lambda a: self._lut(a[0], a[1], a[2], a[3], 8),
            "CB": setr(cursor_on=False, cursor_attach=False), "CA": setr(cursor_on=True),
            "CE": attach, "CF": joystick, "GM": device, "HF": report,
            "KW": arg("write_mask", lambda v: v & pm()),
            "KD": arg("display_mask", lambda v: v & pm()),
            "KQ": view,
        }

    # ------------------------------------------------------------------ display
    def _clip_area(self, x: int, y: int) -> tuple[int, int]:
        m = self.model
        return min(max(x, 0), m.area_w - 1), min(max(y, 0), m.area_h - 1)

    def screen_to_area(self, x: int, y: int) -> tuple[int, int]:
        """Screen pixel (device units, y up) -> drawing-area pixel under the current view."""
        x0, y0, step = display.view_origin(self.model, self.reg.view)
        return self._clip_area(x0 + x * step, y0 + y * step)

    def indices(self) -> np.ndarray:
        """(512, 768) uint8 LUT indices on the screen, row 0 = bottom (device y up)."""
        return display.screen_indices(self.planes, self.model, self.reg.view,
                                      self.reg.display_mask)

    def frame(self) -> np.ndarray:
        """(512, 768, 3) uint8 as displayed, row 0 = top of the screen."""
        return display.compose(self)

    # ------------------------------------------------------------------ local input
    def key(self, char: str) -> None:
        """A key struck on the terminal's keyboard: ends a cursor read (HF) or goes up the line."""
        data = char.encode("latin-1", "replace")
        if not data:
            return
        if self.reg.cursor_report:
            self._report(data[0])
            data = data[1:]
        if data:
            self._send(data)

    def _report(self, key: int) -> None:
        r = self.reg
        r.cursor_report = False
        self._send(format_report(key, r.cursor_x, r.cursor_y, self.decoder.coord_digits))

    def press(self, name: str, shift: bool = False) -> None:
        """A named key of the keyboard (protocols.sigma.keyboard: ``"up"``, ``"f2"``, a
        printable character ...) struck: a cursor key moves the crosshair while a cursor read
        is armed with the crosshair on the keys (Shift: 8 units), every other time it sends
        its code like any key; a name the keyboard has not is ignored."""
        step = CURSOR_STEPS.get(name)
        if step is not None and self.reg.cursor_report and not self.reg.cursor_tablet:
            n = 8 if shift else 1
            self.cursor_keys(step[0] * n, step[1] * n)
        elif name in KEY_BYTES or len(name) == 1:
            self.key(KEY_BYTES[name].decode("latin-1") if name in KEY_BYTES else name)

    def cursor_keys(self, dx: int, dy: int) -> None:
        """Joystick / cursor keys move the crosshair (device units, y up)."""
        r = self.reg
        if not r.cursor_tablet:
            r.cursor_x, r.cursor_y = self._clip_area(r.cursor_x + dx, r.cursor_y + dy)

    def tablet(self, x: int, y: int, pressed: bool) -> None:
        """Stylus at screen (x, y) (device units, y up); a press ends a cursor read."""
        r = self.reg
        if r.cursor_tablet:
            r.cursor_x, r.cursor_y = self.screen_to_area(x, y)
            if pressed and r.cursor_report:
                self._report(TABLET_KEY)

    # ------------------------------------------------------------------ state
    def own_state(self) -> tuple[Registers, np.ndarray, np.ndarray, int]:
        """The terminal's own part of a saved state (its parts save theirs: the decoder's
        get_state, the alpha screen's save_state): registers, planes, LUT, error count."""
        return self.reg, self.planes, self.lut, self.errors

    def restore_own(self, reg: Registers, planes: np.ndarray, lut: np.ndarray,
                    errors: int) -> None:
        """Put back own_state()'s values (the caller has checked their shapes)."""
        if planes.shape != self.planes.shape or lut.shape != self.lut.shape:
            raise ValueError("Sigma state arrays have the wrong shapes for this model")
        self.reg, self.errors = reg, errors
        self.planes = np.array(planes, dtype=np.uint8)
        self.lut = np.array(lut, dtype=np.uint8)

    def save_state(self, compress: bool = True) -> bytes:
        from camlab88.emulator.sigma.state import save

        return save(self, compress)

    def load_state(self, data: bytes) -> None:
        from camlab88.emulator.sigma.state import load

        load(self, data)
