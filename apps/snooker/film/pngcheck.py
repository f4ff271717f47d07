"""Is a frame on disk finished? A resumed film skips a frame only when its PNG decodes
whole and has the film's size (a torn or foreign file is rendered again)."""

from __future__ import annotations

import io
import os


def png_size(data: bytes) -> tuple[int, int] | None:
    """(width, height) of a PNG that decodes completely, else None."""
    from PIL import Image

    try:
        with Image.open(io.BytesIO(data)) as im:
            if im.format != "PNG":
                return None
            im.load()  # decodes every row: a truncated file fails here
            if im.mode != "RGB":
                return None
            return im.size
    except (OSError, ValueError, SyntaxError):
        return None


def is_complete(path: str | os.PathLike[str], size: tuple[int, int]) -> bool:
    try:
        with open(path, "rb") as fh:
            data = fh.read()
    except OSError:
        return False
    return png_size(data) == size
