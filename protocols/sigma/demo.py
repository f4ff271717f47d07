"""The demo session's Sigma T5684 host program: byte streams built with protocols.sigma's
Encoder the way a host program would send them (for ``camlab88 demo`` and the shipped
example streams).

The still picture shows abbreviated-mode vectors, dash masks, firmware text, ellipses, a
flood fill and solid blocks; the animation cycles the LUT and then double-buffers in two
2-bit buffers through the LUT (thesis §3.1.4).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from camlab88.protocols.sigma import Encoder


def sigma_demo_stream() -> bytes:
    """The whole session: the still picture, then LUT animation and double buffering."""
    return sigma_picture_stream() + sigma_animation_stream()


def sigma_picture_stream() -> bytes:
    """The still part: vectors, dash masks, text, ellipses, flood fill, solid blocks."""
    from camlab88.protocols.sigma import Encoder

    e = Encoder()
    parts = (_power_on, _vectors, _dash_masks, _ellipses, _flood_fill, _blocks)
    return b"".join(part(e) for part in parts)


def _power_on(e: Encoder) -> bytes:
    """A banner on the alpha screen, then into graphics as the RAL GKS driver does; a LUT."""
    out = (e.take_over() + e.sequence_length(0)
           + e.graphics_on() + e.alpha_on() + e.alpha_mode()
           + b"camlab88: Sigma T5684 on a 9600 baud line\r\n" + b"\r" + e.flag() + e.cursor_off())
    for i, rgb in enumerate(((0, 0, 0), (15, 15, 15), (15, 3, 3), (3, 15, 3), (4, 6, 15),
                             (15, 15, 2), (15, 4, 15), (3, 15, 15))):
        out += e.lut(i, *rgb)
    return out


def _vectors(e: Encoder) -> bytes:
    """1. A star of vectors in abbreviated mode."""
    cx, cy = 200, 330
    out = e.colour(7)
    for k in range(24):
        a = 2 * math.pi * k / 24
        out += e.abbreviated_polyline([(cx, cy), (cx + int(150 * math.cos(a)),
                                                  cy + int(150 * math.sin(a)))])
    return out + e.colour(1) + e.move(40, 462) + e.text("VECTORS (ABBREVIATED MODE)")


def _dash_masks(e: Encoder) -> bytes:
    """2. Dash masks, continuing across vectors."""
    out, y = b"", 300
    for colour, mask in ((2, 0xF0F0), (3, 0x8888), (5, 0xFE10), (6, 0xF888)):
        out += e.colour(colour) + e.dash(mask)
        out += e.abbreviated_polyline([(400, y), (500, y + 40), (600, y), (720, y + 40)])
        y += 35
    return (out + e.line_reset() + e.line_solid()
            + e.colour(1) + e.move(400, 462) + e.text("DL DASH MASKS"))


def _ellipses(e: Encoder) -> bytes:
    """3. Firmware ellipses."""
    out = b""
    for k, (x, r, ratio, solid) in enumerate(((460, 40, 1.0, False), (560, 45, 1.8, True),
                                              (670, 35, 0.6, False))):
        out += e.colour(2 + k) + e.move(x, 200) + e.ellipse(r, ratio, solid)
    return out + e.colour(1) + e.move(430, 130) + e.text("JO/JM/JN ELLIPSES")


def _flood_fill(e: Encoder) -> bytes:
    """4. A polygon outline and the firmware flood fill from a seed inside it."""
    pts = [(60, 40), (330, 60), (260, 150), (170, 110), (90, 170), (60, 40)]
    return (e.colour(5) + e.polyline(pts) + e.colour(4) + e.move(120, 80) + e.fill(5)
            + e.colour(1) + e.move(40, 15) + e.text("JK FLOOD FILL"))


def _blocks(e: Encoder) -> bytes:
    """5. Solid blocks: a colour bar."""
    return b"".join(e.colour(k) + e.move(420 + 40 * k, 20) + e.block(450 + 40 * k, 60)
                    for k in range(8))


def sigma_animation_stream() -> bytes:
    from camlab88.protocols.sigma import Encoder

    e = Encoder()
    out = bytearray()
    put = out.extend
    # 6. LUT animation: concentric rings in entries 8..15, cycled by JG only
    for k in range(8):
        put(e.colour(8 + k) + e.move(200, 330) + e.ellipse(60 - 7 * k, 1.0, True))
    ramp = [(15, 2 * k, 0) for k in range(8)]
    for step in range(32):
        for k in range(8):
            put(e.lut(8 + k, *ramp[(k + step) % 8]))
    put(e.alpha_mode() + b"LUT animation done; now double buffering (thesis 3.1.4)\r\n")
    put(b"\r" + e.flag())

    # 7. double buffering: planes 0-1 = buffer A, planes 2-3 = buffer B
    put(e.erase())
    lut_show_a = [(0, 0, 0), (15, 15, 15), (15, 8, 0), (0, 10, 15)]
    for idx in range(16):  # show buffer A (empty) while B is drawn
        put(e.lut(idx, *lut_show_a[idx & 3]))
    for frame in range(24):
        draw_b = frame % 2 == 0  # draw into the hidden buffer
        shift = 2 if draw_b else 0
        put(e.write_mask(0b11 << shift) + e.erase())
        put(e.colour(1 << shift))
        a = 2 * math.pi * frame / 24
        square = [(384 + int(120 * math.cos(a + q * math.pi / 2)),
                   256 + int(120 * math.sin(a + q * math.pi / 2))) for q in range(5)]
        put(e.abbreviated_polyline(square))
        put(e.colour(2 << shift) + e.move(384, 256) + e.ellipse(20 + 2 * frame, 1.0, True))
        # swap: make the LUT show the buffer just drawn (index bits of that buffer only)
        for idx in range(16):
            v = (idx >> shift) & 3
            put(e.lut(idx, *lut_show_a[v]))
    put(e.write_mask(15) + e.alpha_mode() + b"end of demo\r\n")
    return bytes(out)


