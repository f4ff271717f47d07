"""The one table of Sigma T5684/T5688 orders: the encoder formats from it, the decoder parses by it.

Each order is two upper-case letters followed by fixed-width fields. ``status`` says where the
order comes from: ``FACT <source ids>`` (seen in a real driver, see docs/fidelity/sigma.md),
``INFERENCE`` (the bytes are a fact, the meaning a reading) or ``RECONSTRUCTED`` (no public source
shows such an order; we chose the letters and format so that the thesis's programs can work).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class Kind(Enum):
    DEC = "dec"  # ASCII decimal digits, fixed width
    HEX = "hex"  # ASCII hex digits 0-9 A-F, fixed width


class Mode(Enum):
    """The decoder's state after an order (``None`` in the table: stay in NGS)."""

    ALPHA = "alpha"  # BH: bytes are alpha-screen text until the graphics flag
    NGS = "ngs"  # normal graphics set: two-letter orders and decimal coordinate pairs
    AGS = "ags"  # abbreviated graphics set (JH ... US): Tektronix-style coordinate bytes
    DOTS = "dots"  # sequential dot plotting (DJ ... Z): one hex digit per pixel
    TEXT = "text"  # graphics text (BA ... CR)


@dataclass(frozen=True, slots=True)
class Field:
    name: str
    kind: Kind
    width: int

    @property
    def maximum(self) -> int:
        return (10 if self.kind is Kind.DEC else 16) ** self.width - 1


@dataclass(frozen=True, slots=True)
class OrderSpec:
    code: str  # the two order letters, e.g. "GI"
    name: str  # the register/behaviour the order names, used for Encoder methods and docs
    fields: tuple[Field, ...]
    meaning: str
    status: str
    mode: Mode | None = None


def _d(name: str, width: int) -> Field:
    return Field(name, Kind.DEC, width)


def _h(name: str, width: int) -> Field:
    return Field(name, Kind.HEX, width)


GRAPHICS_FLAG = b"+-*/"
US = 0x1F  # leaves abbreviated mode
ESC = 0x1B
CR = 0x0D
LF = 0x0A
FF = 0x0C

ORDERS: tuple[OrderSpec, ...] = (
    # --- mode, initialisation, screen (facts/sigma.md 5.1)
    OrderSpec("BH", "alpha_mode", (), "return to alpha mode", "FACT S1 S3", Mode.ALPHA),
    OrderSpec("HH", "reset", (), "initialise incl. clear screen (host then sends 10 NULs)",
              "FACT S2; LUT reload RECONSTRUCTED"),
    OrderSpec("DD", "sequence_length", (_d("value", 3),),
              "DD000: allow any length graphics sequences", "FACT S1 S2"),
    OrderSpec("DG", "xon_char", (_d("char", 3),), "set the XON character (DG017)",
              "FACT S2 bytes; meaning INFERENCE"),
    OrderSpec("DF", "xoff_char", (_d("char", 3),), "set the XOFF character (DF019)",
              "FACT S2 bytes; meaning INFERENCE"),
    OrderSpec("GA", "graphics_on", (), "graphics display on", "FACT S1 S2"),
    OrderSpec("AA", "alpha_on", (), "alpha display on", "FACT S1 S3"),
    OrderSpec("AJ", "alpha_off", (), "alpha display off", "FACT S2 bytes; meaning GUESS"),
    OrderSpec("HE", "prompt_char", (_d("value", 3),),
              "HE999: disable the cursor prompt character", "FACT S1 comment; split INFERENCE"),
    OrderSpec("CK", "cursor_shape", (_d("shape", 1),), "CK1: full-screen crosshair cursor",
              "FACT S1 S2"),
    OrderSpec("GH", "flag_anywhere", (),
              "recognise the graphics flag any time in alpha mode", "FACT S1 S2"),
    OrderSpec("IE", "normal_mode", (), "5660: set normal mode (joystick)", "FACT S2"),
    OrderSpec("IO", "coords4", (), "4-digit absolute coordinates", "FACT S2"),
    OrderSpec("IP", "coords3", (), "3-digit absolute coordinates (the default)", "FACT S2"),
    OrderSpec("DA", "erase", (), "clear the display surface", "FACT S1 S2 S6"),
    # --- drawing (5.2)
    OrderSpec("GI", "pen_up", (), "pen up: following pairs move", "FACT S1 S6"),
    OrderSpec("GJ", "pen_down", (), "pen down: following pairs draw", "FACT S1 S6"),
    OrderSpec("FA", "pen_draw", (), "PGPLOT colour index 1 (draw)", "FACT S1"),
    OrderSpec("FB", "pen_erase", (), "PGPLOT colour index 0 (erase)", "FACT S1"),
    OrderSpec("FC", "line_solid", (), "solid lines (line mode reset)",
              "FACT S2 S6 bytes; meaning INFERENCE"),
    OrderSpec("FD", "line_dashed", (), "dashed lines using the current dash mask",
              "FACT S2 bytes; meaning INFERENCE"),
    OrderSpec("FG", "line_reset", (), "part of FGFC 'reset linetype': restarts the dash phase",
              "FACT S2 bytes; meaning RECONSTRUCTED"),
    OrderSpec("DL", "dash_mask", (_h("mask", 4),), "16-bit dash mask, MSB first, 1 = on",
              "FACT S2; bit order INFERENCE"),
    OrderSpec("EK", "dash_mask12", (_h("mask", 3),), "NGS form of AGS ESC M (12-bit mask)",
              "FACT S2 comment; format RECONSTRUCTED"),
    OrderSpec("HI", "colour", (_h("colour", 1),), "current drawing colour index 0-F",
              "FACT S2 S6"),
    OrderSpec("BA", "text", (), "graphics text at the pen, up to CR", "FACT S6 use; CR INFERENCE",
              Mode.TEXT),
    OrderSpec("FH", "solid_shape", (), "GJ FH BG xxxyyy: the next block is solid",
              "FACT S6 bytes; split RECONSTRUCTED"),
    OrderSpec("BG", "block", (), "GJ FH BG xxxyyy: the next point is a block corner",
              "FACT S6 bytes; split RECONSTRUCTED"),
    OrderSpec("DJ", "dot_plot", (), "sequential dot plotting, one hex digit per pixel, +X",
              "FACT S3; +X INFERENCE", Mode.DOTS),
    # --- firmware shapes and fill (5.3)
    OrderSpec("JK", "fill", (_h("boundary", 1),),
              "boundary flood fill from the pen in the drawing colour", "FACT S6; meaning brief"),
    OrderSpec("JO", "ellipse_ratio", (_d("ratio", 3),), "ellipse shape: 256*major/minor + 100",
              "FACT S6 bytes; meaning INFERENCE"),
    OrderSpec("JM", "ellipse", (_d("size", 4),), "outline ellipse at the pen: 10*(a + 100)",
              "FACT S6 bytes; meaning INFERENCE"),
    OrderSpec("JN", "ellipse_solid", (_d("size", 4),), "solid ellipse at the pen: 10*(a + 100)",
              "FACT S6 bytes; meaning INFERENCE"),
    # --- abbreviated mode (5.4)
    OrderSpec("JH", "abbreviated", (), "enter abbreviated graphics mode (AGS) until US",
              "FACT S3", Mode.AGS),
    # --- colour lookup table (5.5)
    OrderSpec("JG", "lut", (_h("index", 1), _h("red", 1), _h("green", 1), _h("blue", 1),
                            _h("ext", 1)),
              "LUT entry: index, 4-bit red, green, blue, trailing 0", "FACT S2"),
    # --- cursor (7)
    OrderSpec("CB", "cursor_off", (), "graphics cursor off", "FACT S1 S3"),
    OrderSpec("CA", "cursor_on", (), "graphics cursor on", "FACT S1 S3"),
    OrderSpec("CE", "cursor_attach", (), "attach the graphics cursor to the pen", "FACT S3"),
    OrderSpec("CF", "cursor_joystick", (), "cursor input from the joystick / cursor keys",
              "FACT S3"),
    OrderSpec("GM", "cursor_device", (_d("device", 1),), "GM3: cursor input from the tablet",
              "FACT S3"),
    OrderSpec("HF", "cursor_report", (),
              "report key, X, comma, Y, CR when a key is struck", "FACT S1 S3; format decision"),
    # --- reconstructed: what the thesis's programs need and no driver shows
    OrderSpec("KW", "write_mask", (_h("mask", 2),), "plane write-enable mask (1 = writable)",
              "RECONSTRUCTED (thesis 3.1.4, 3.3; ARGS ZWE analogue)"),
    OrderSpec("KD", "display_mask", (_h("mask", 2),),
              "plane display/read mask: planes seen by the LUT and by fill",
              "RECONSTRUCTED (thesis 3.3; ARGS ZDI analogue)"),
    OrderSpec("KI", "colour8", (_h("colour", 2),), "8-bit drawing colour index (T5688)",
              "RECONSTRUCTED (thesis 3.3, 6.4.1)"),
    OrderSpec("KK", "fill8", (_h("boundary", 2),), "flood fill with an 8-bit boundary colour",
              "RECONSTRUCTED (thesis 3.3)"),
    OrderSpec("KG", "lut24", (_h("index", 2), _h("red", 2), _h("green", 2), _h("blue", 2)),
              "24-bit LUT entry (T5688)", "RECONSTRUCTED (thesis 3.3; ARGS 8-bit guns)"),
    OrderSpec("KQ", "view", (_d("view", 1),),
              "T5688 view: 0-3 show a quadrant, 4 the whole area at half size",
              "RECONSTRUCTED (thesis 3.3; PLT2D quadrant mode)"),
)

BY_CODE: dict[bytes, OrderSpec] = {o.code.encode("ascii"): o for o in ORDERS}
BY_NAME: dict[str, OrderSpec] = {o.name: o for o in ORDERS}
FIRST_LETTERS: frozenset[int] = frozenset(o.code.encode()[0] for o in ORDERS)

assert len(BY_CODE) == len(ORDERS) and len(BY_NAME) == len(ORDERS), "duplicate order"


def format_field(field: Field, value: int) -> bytes:
    """Format one field; raises ValueError naming the field when out of range."""
    if not 0 <= int(value) <= field.maximum:
        raise ValueError(f"{field.name}={value} does not fit {field.width} {field.kind.value} "
                         f"digit(s)")
    if field.kind is Kind.DEC:
        return f"{int(value):0{field.width}d}".encode("ascii")
    return f"{int(value):0{field.width}X}".encode("ascii")


def digit_value(kind: Kind, byte: int) -> int:
    """Value of one parameter digit, or -1 if ``byte`` is not a digit of that kind."""
    if 0x30 <= byte <= 0x39:
        return byte - 0x30
    if kind is Kind.HEX:
        if 0x41 <= byte <= 0x46:
            return byte - 0x41 + 10
        if 0x61 <= byte <= 0x66:
            return byte - 0x61 + 10
    return -1
