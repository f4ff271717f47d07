"""Host-side encoder: typed calls -> Sigma bytes, formatted from the same order table.

Every order of protocols.sigma.orders is available as a method named after the order
(``enc.lut(3, 15, 0, 0, 0)``, ``enc.erase()``, or generically ``enc.order("JG", ...)``);
the richer helpers below add coordinates (excess-100 decimal or abbreviated mode), text,
dot runs, ellipses and blocks. Each call returns the bytes; nothing is buffered here.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence

from camlab88.protocols.sigma.abbreviated import AgsPointEncoder
from camlab88.protocols.sigma.orders import (
    BY_CODE,
    BY_NAME,
    CR,
    ESC,
    GRAPHICS_FLAG,
    ORDERS,
    US,
    OrderSpec,
    format_field,
)

EXCESS = 100  # NGS decimal fields carry value + 100 (facts/sigma.md 4.1)


class Encoder:
    """Builds Sigma command bytes. ``high_res`` adds the AGS extra byte (T5688 drawing area)."""

    def __init__(self, high_res: bool = False) -> None:
        self.high_res = high_res
        self.coord_digits = 3

    # ------------------------------------------------------------ table-driven
    def order(self, code: str, *args: int) -> bytes:
        spec = BY_CODE.get(code.encode("ascii"))
        if spec is None:
            raise ValueError(f"unknown Sigma order {code!r}")
        if len(args) != len(spec.fields):
            raise ValueError(f"{code} takes {len(spec.fields)} field(s), got {len(args)}")
        try:
            body = b"".join(format_field(f, v) for f, v in zip(spec.fields, args))
        except ValueError as exc:
            raise ValueError(f"{code}: {exc}") from None
        if code == "IO":
            self.coord_digits = 4
        elif code in ("IP", "HH"):
            self.coord_digits = 3
        return spec.code.encode("ascii") + body

    # ------------------------------------------------------------ framing
    @staticmethod
    def flag() -> bytes:
        return GRAPHICS_FLAG

    def reset(self) -> bytes:
        """HH and the ten NULs that let the device settle (RAL GKS)."""
        return self.order("HH") + bytes(10)

    # ------------------------------------------------------------ coordinates
    def pair(self, x: int, y: int) -> bytes:
        """A bare excess-100 coordinate pair (3 digits each, 4 after IO)."""
        w = self.coord_digits
        top = 10**w - 1 - EXCESS
        if not (-EXCESS <= x <= top and -EXCESS <= y <= top):
            raise ValueError(f"point ({x}, {y}) outside -100..{top} for {w}-digit coordinates")
        return f"{x + EXCESS:0{w}d}{y + EXCESS:0{w}d}".encode("ascii")

    def move(self, x: int, y: int) -> bytes:
        return b"GI" + self.pair(x, y)

    def draw(self, x: int, y: int) -> bytes:
        return b"GJ" + self.pair(x, y)

    def polyline(self, points: Sequence[tuple[int, int]]) -> bytes:
        """NGS polyline: GI first point, GJ, then bare pairs (each keeps drawing)."""
        if not points:
            return b""
        out = [self.move(*points[0])]
        if len(points) > 1:
            out.append(b"GJ")
            out.extend(self.pair(x, y) for x, y in points[1:])
        return b"".join(out)

    def abbreviated_polyline(self, points: Iterable[tuple[int, int]]) -> bytes:
        """AGS polyline: JH, Tek-style points (the first one moves), US."""
        enc = AgsPointEncoder(self.high_res)
        return b"JH" + b"".join(enc.encode(x, y) for x, y in points) + bytes((US,))

    # ------------------------------------------------------------ drawing helpers
    def text(self, text: str | bytes) -> bytes:
        """BA graphics text at the pen, terminated by CR."""
        data = text.encode("ascii") if isinstance(text, str) else bytes(text)
        if any(not 0x20 <= b <= 0x7E for b in data):
            raise ValueError("graphics text must be printable ASCII")
        return b"BA" + data + bytes((CR,))

    def dots(self, colours: Iterable[int]) -> bytes:
        """DJ sequential dot plotting from the pen, one hex digit per pixel, then Z."""
        digits = bytearray()
        for c in colours:
            if not 0 <= c <= 15:
                raise ValueError(f"dot colour {c} outside 0..15")
            digits += b"%X" % c
        return b"DJ" + bytes(digits) + b"Z"

    def block(self, x: int, y: int, solid: bool = True) -> bytes:
        """Block from the pen to (x, y): GJ FH BG xxxyyy (CRYSTALS' solid block)."""
        return b"GJ" + (b"FH" if solid else b"") + b"BG" + self.pair(x, y)

    def ellipse(self, major: float, ratio: float = 1.0, solid: bool = False) -> bytes:
        """JO ratio then JM/JN radius at the pen; ``ratio`` = major / minor (CRYSTALS units)."""
        jo = int(256 * ratio) + EXCESS
        size = int(round((major + EXCESS) * 10))
        return self.order("JO", jo) + self.order("JN" if solid else "JM", size)

    def dash(self, mask: int) -> bytes:
        """DL mask then FD: dashed lines (B series, 16-bit mask)."""
        return self.order("DL", mask) + self.order("FD")

    def abbreviated_dash12(self, mask: int) -> bytes:
        """A-series 12-bit mask: JH ESC M hhh US FD (RAL GKS)."""
        if not 0 <= mask <= 0xFFF:
            raise ValueError(f"12-bit mask {mask:#x} out of range")
        return b"JH" + bytes((ESC,)) + b"M%03X" % mask + bytes((US,)) + self.order("FD")

    def lut(self, index: int, red: int, green: int, blue: int, ext: int = 0) -> bytes:
        return self.order("JG", index, red, green, blue, ext)

    # ------------------------------------------------------------ a host's opening bytes
    def take_over(self) -> bytes:
        """CR, the flag, HH reset and flag-anywhere: the terminal in graphics mode from
        whatever state a previous program left it in (every host's first bytes)."""
        return b"\r" + self.flag() + self.reset() + self.flag_anywhere()

    def full_colour_screen(self) -> bytes:
        """Graphics only (no alpha, no cursor), all eight planes written and shown, quadrant
        0 on screen, solid lines: the T5688 as one 256-colour picture."""
        return (self.sequence_length(0) + self.graphics_on() + self.alpha_off()
                + self.cursor_off() + self.write_mask(0xFF) + self.display_mask(0xFF)
                + self.view(0) + self.line_solid())

    def lut24_table(self, lut: Iterable[Sequence[int]]) -> bytes:
        """KG for entries 0, 1, ... of a table of (red, green, blue) bytes (T5688)."""
        return b"".join(self.lut24(i, r, g, b) for i, (r, g, b) in enumerate(lut))

    def colour(self, index: int) -> bytes:
        """HI for 0..15, the reconstructed 8-bit KI above that (T5688)."""
        return self.order("HI", index) if index < 16 else self.order("KI", index)


def _make_method(spec: OrderSpec) -> Callable[..., bytes]:
    def method(self: Encoder, *args: int) -> bytes:
        return self.order(spec.code, *args)

    method.__name__ = spec.name
    fields = ", ".join(f.name for f in spec.fields)
    method.__doc__ = f"{spec.code}({fields}): {spec.meaning} [{spec.status}]"
    return method


for _spec in ORDERS:
    if not hasattr(Encoder, _spec.name):
        setattr(Encoder, _spec.name, _make_method(_spec))

assert all(hasattr(Encoder, name) for name in BY_NAME)
