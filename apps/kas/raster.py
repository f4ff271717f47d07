"""A plain software rasteriser for exporting sequences as pictures (``--renderer raster``).

The default export (``kas export``, ``--renderer sigma``) draws each frame on the emulated
Sigma T5684 and saves what that screen shows.  This one draws with Pillow at any size (the
twelve-field fills the image), in the thesis palette on a black or white background: for
pictures larger than the Sigma's 768x512, and for the README's contact sheets.
"""

from __future__ import annotations

import numpy as np
from PIL import Image, ImageDraw

from camlab88.apps.kas.model import FIELD_H, FIELD_W, PALETTE, Drawing


def image_size(width: int) -> tuple[int, int]:
    return width, round(width * FIELD_H / FIELD_W)


def render(frame: Drawing, width: int = 768, background: str = "black") -> np.ndarray:
    """(h, w, 3) uint8 picture of a frame; only the twelve-field is shown."""
    w, h = image_size(width)
    bg = (0, 0, 0) if background == "black" else (255, 255, 255)
    img = Image.new("RGB", (w, h), bg)
    draw = ImageDraw.Draw(img)
    s = w / FIELD_W
    for chain in frame.chains:
        px = np.column_stack([(chain.points[:, 0] + FIELD_W / 2) * s,
                              (FIELD_H / 2 - chain.points[:, 1]) * s])
        cols = chain.colours
        for i in range(len(px)):
            rgb = PALETTE.get(int(cols[i]), ("", (255, 255, 255)))[1]
            if background != "black" and int(cols[i]) == 1:
                rgb = (0, 0, 0)
            if i == 0:
                if len(px) == 1:
                    draw.point(tuple(px[0]), fill=rgb)
                continue
            draw.line([tuple(px[i - 1]), tuple(px[i])], fill=rgb, width=1)
    return np.asarray(img)
